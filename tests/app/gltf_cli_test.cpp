// `--scene FILE.gltf` through the binary: a light-only file renders; a bad file is one line and
// exit code 2, with nothing written.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

class GltfCli : public ::testing::Test {
 protected:
  void SetUp() override {
    temp_ = std::make_unique<levrt_test::TempDir>(
        "levrt_gltf_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_");
    dir_ = temp_->path();
  }
  void TearDown() override { temp_.reset(); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::unique_ptr<levrt_test::TempDir> temp_;
  fs::path dir_;
};

std::string gltf_with_light(const std::string& light) {
  return R"({"asset": {"version": "2.0"}, "extensions": {"KHR_lights_punctual": {"lights": [)" +
         light +
         R"(]}}, "scenes": [{"nodes": [0]}], "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]})";
}

TEST_F(GltfCli, LightFileRenders) {
  const std::string file = path("lamp.gltf");
  { std::ofstream(file) << gltf_with_light(R"({"type": "point", "intensity": 3})"); }
  const CommandRun r = run_levrt(
      {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 lights"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(path("x.png")));
}

TEST_F(GltfCli, BadFilesExitTwoWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bad.gltf", gltf_with_light(R"({"type": "point", "intensity": -5})")},
      {"bad.gltf", "{\"asset\": "},
      {"bad.glb", "glTF\x02\x00\x00\x00\xff\xff\xff\x7f"},
  };
  for (const auto& [name, text] : cases) {
    const std::string file = path(name);
    { std::ofstream(file, std::ios::binary) << text; }
    const CommandRun r = run_levrt(
        {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(file + ": "), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
}

// A file with one triangle whose three positions (36 bytes) live in the buffer at bin_uri.
std::string gltf_with_bin(const std::string& bin_uri, std::size_t bin_bytes) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + bin_uri +
         R"(", "byteLength": )" + std::to_string(bin_bytes) +
         R"(}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}]})";
}

std::string floats_bytes(const std::vector<float>& values) {
  std::string bytes(values.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// Broken glTF files through the binary: each is one line naming the file, exit 2, and
// no image.
TEST_F(GltfCli, EveryKindOfBrokenFileExitsTwoWithOneLine) {
  const std::string triangle = floats_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const std::string nan_triangle = floats_bytes({0, 0, 0, 1, 0, 0, 0, std::nanf(""), 0});
  const std::string glb_header = std::string("glTF") + std::string("\x02\0\0\0", 4);
  std::string wrong_chunk = R"({"asset": {"version": "2.0"}})";
  while (wrong_chunk.size() % 4 != 0) wrong_chunk += ' ';
  const auto word = [](std::uint32_t v) {
    return std::string(reinterpret_cast<const char*>(&v), 4);
  };
  const std::string glb_wrong_chunk =
      glb_header + word(static_cast<std::uint32_t>(20 + wrong_chunk.size())) +
      word(static_cast<std::uint32_t>(wrong_chunk.size())) + "BIN\0" + wrong_chunk;
  struct Case {
    std::string name, text, bin, problem;
  };
  const std::vector<Case> cases = {
      {"missing_bin.gltf", gltf_with_bin("absent.bin", 36), "", "absent.bin"},
      {"short_bin.gltf", gltf_with_bin("short.bin", 36), triangle.substr(0, 20), ""},
      {"nan.gltf", gltf_with_bin("nan.bin", 36), nan_triangle, "nan"},
      {"bad_uri.gltf", gltf_with_bin("data:application/octet-stream;base64,@@@@", 36), "", ""},
      {"huge.gltf",
       R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
           "bufferViews": [{"buffer": 0, "byteLength": 12}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 4000000000}],
           "scenes": [{"nodes": []}]})",
       "", "4000000000"},
      {"inf_light.gltf", gltf_with_light(R"({"type": "point", "intensity": 1e999})"), "", "1e999"},
      {"negative_range.gltf", gltf_with_light(R"({"type": "point", "range": -0.5})"), "", "range"},
      {"cone.gltf", gltf_with_light(R"({"type": "spot", "spot": {"outerConeAngle": 1.6}})"), "",
       "outerConeAngle"},
      {"cycle.gltf",
       R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"children": [0]}]})",
       "", "cycle"},
      {"chunk.glb", glb_wrong_chunk, "", ""},
      {"length.glb", glb_header + word(9999) + word(8) + "JSON" + "{}      ", "", ""},
  };
  for (const Case& c : cases) {
    const std::string file = path(c.name);
    { std::ofstream(file, std::ios::binary) << c.text; }
    if (!c.bin.empty()) {
      std::ofstream(path(c.name == "short_bin.gltf" ? "short.bin" : "nan.bin"), std::ios::binary)
          << c.bin;
    }
    const CommandRun r = run_levrt({"render", "--scene", file, "--width", "8", "--height", "8",
                                    "--out", path("x.png"), "--stats", path("s.json")});
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.output;
    EXPECT_EQ(r.output.rfind("levrt: " + file + ": ", 0), 0u) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.problem), std::string::npos) << c.name << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.name << ": " << r.output;
    EXPECT_FALSE(fs::exists(path("x.png"))) << c.name;
    EXPECT_FALSE(fs::exists(path("s.json"))) << c.name;
  }
}

TEST_F(GltfCli, AFileWithNothingToRenderShowsTheBackgroundWithOneWarning) {
  const std::string file = path("empty.gltf");
  {
    std::ofstream(file)
        << R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
      "bufferViews": [{"buffer": 0, "byteLength": 12}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 1}],
      "scenes": [{"nodes": [0]}], "nodes": [{"name": "empty"}]})";
  }
  const CommandRun r = run_levrt(
      {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(file + ": warning: nothing to render"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 3)
      << r.output;  // warning, wrote, summary
  EXPECT_TRUE(fs::exists(path("x.png")));
}

}  // namespace
