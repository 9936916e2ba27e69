// `--scene FILE.gltf` through the binary: a light-only file renders; a bad file is one line and
// exit code 2, with nothing written.

#include <algorithm>
#include <filesystem>
#include <memory>
#include <fstream>
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

}  // namespace
