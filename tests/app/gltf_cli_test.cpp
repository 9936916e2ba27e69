// `--scene FILE.gltf` through the binary: a light-only file renders; a bad file is one line and
// exit code 2, with nothing written.

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/folder_test.h"
#include "tests/support/gltf_files.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

class GltfCli : public levrt_test::FolderTest {};

std::string gltf_with_light(const std::string& light) {
  return R"({"asset": {"version": "2.0"}, "extensions": {"KHR_lights_punctual": {"lights": [)" +
         light +
         R"(]}}, "scenes": [{"nodes": [0]}], )"
         R"("nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]})";
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

// A render of `file` refused: exit 2, one line naming the file and `problem`, no x.png or
// s.json.
void expect_refused_without_output(const CommandRun& r, const std::string& file,
                                   const std::string& problem) {
  const fs::path folder = fs::path(file).parent_path();
  EXPECT_EQ(r.exit_code, 2) << file << ": " << r.output;
  EXPECT_EQ(r.output.rfind("levrt: " + file + ": ", 0), 0u) << file << ": " << r.output;
  EXPECT_NE(r.output.find(problem), std::string::npos) << file << ": " << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << file << ": " << r.output;
  EXPECT_FALSE(fs::exists(folder / "x.png")) << file;
  EXPECT_FALSE(fs::exists(folder / "s.json")) << file;
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
       R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12,
           "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
           "bufferViews": [{"buffer": 0, "byteLength": 12}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3",
                          "count": 4000000000}],
           "scenes": [{}]})",
       "", "4000000000"},
      {"inf_light.gltf", gltf_with_light(R"({"type": "point", "intensity": 1e999})"), "", "1e999"},
      {"negative_range.gltf", gltf_with_light(R"({"type": "point", "range": -0.5})"), "", "range"},
      {"cone.gltf", gltf_with_light(R"({"type": "spot", "spot": {"outerConeAngle": 1.6}})"), "",
       "outerConeAngle"},
      {"cycle.gltf",
       R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
            "nodes": [{"children": [1]}, {"children": [0]}]})",
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
    expect_refused_without_output(r, file, c.problem);
  }
}

// What glTF forbids (scenes/gltf_schema.h, gltf_node_tree.h, gltf_document.h) through `render`:
// one line naming the file and the glTF path, exit 2, nothing written.
TEST_F(GltfCli, NonConformingFilesExitTwoWithOneLineNamingTheGltfPath) {
  const std::string node = R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})";
  const auto with = [&](const std::string& asset, const std::string& top, const std::string& light,
                        const std::string& nodes, const std::string& roots) {
    return R"({"asset": )" + asset + top +
           R"(, "extensions": {"KHR_lights_punctual": {"lights": [)" + light +
           R"(]}}, "scenes": [{"nodes": )" + roots + R"(}], "nodes": [)" + nodes + "]}";
  };
  const std::string v2 = R"({"version": "2.0"})";
  const std::string point = R"({"type": "point"})";
  std::string glb_json = with(v2, "", point, node, "[0]");
  while (glb_json.size() % 4 != 0) glb_json += ' ';
  const auto word = [](std::uint32_t v) {
    return std::string(reinterpret_cast<const char*>(&v), 4);
  };
  const std::string glb = std::string("glTF") + word(2) +
                          word(static_cast<std::uint32_t>(20 + glb_json.size())) +
                          word(static_cast<std::uint32_t>(glb_json.size())) + "JSON" + glb_json;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with(v2, R"(, "extensionsRequired": ["KHR_draco_mesh_compression"])", point, node, "[0]"),
       "extensionsRequired[0]: 'KHR_draco_mesh_compression'"},
      {with(R"({"version": "1.0"})", "", point, node, "[0]"), "asset.version: '1.0'"},
      {with(R"({"version": "2.0", "minVersion": "2.1"})", "", point, node, "[0]"),
       "asset.minVersion: '2.1'"},
      {with(v2, "", R"({"type": "point", "intensity": "50"})", node, "[0]"),
       "extensions.KHR_lights_punctual.lights[0].intensity: '50'"},
      {with(v2, "", R"({"type": "point", "range": 0})", node, "[0]"),
       "extensions.KHR_lights_punctual.lights[0].range: 0"},
      // Above levrt's bound: named by its glTF path, not the scene node built from it.
      {with(v2, "", R"({"type": "point", "intensity": 1e30})", node, "[0]"),
       "extensions.KHR_lights_punctual.lights[0].intensity: 1e+30 (levrt renders at most 1e+12)"},
      {with(v2, "", R"({"type": "directional", "intensity": 1e13})", node, "[0]"),
       "extensions.KHR_lights_punctual.lights[0].intensity: 1e+13"},
      {with(v2, "", point, node + R"(, {"children": [0]}, {"children": [0]})", "[1, 2]"),
       "nodes[0]: a child of both nodes[1] and nodes[2]"},
      {glb + "    ", "binary glTF: header length"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string file =
        path("case" + std::to_string(i) + (i + 1 == cases.size() ? ".glb" : ".gltf"));
    { std::ofstream(file, std::ios::binary) << cases[i].first; }
    const CommandRun r = run_levrt({"render", "--scene", file, "--width", "8", "--height", "8",
                                    "--out", path("x.png"), "--stats", path("s.json")});
    expect_refused_without_output(r, file, cases[i].second);
  }
}

// An orthographic camera's ymag is a length like any other, at most 1e6: rays start up to ymag
// (times the aspect ratio) from the camera, and Embree aborts on ray origins past about 1.8e18
// (ymag 1e25 was exit 134). The limit itself renders.
TEST_F(GltfCli, AnOrthographicCameraOfHugeMagnitudeIsRefusedAndTheLimitRenders) {
  const auto with_ymag = [](const std::string& ymag) {
    return R"({"asset": {"version": "2.0"}, "extensions": {"KHR_lights_punctual": {"lights": [)"
           R"({"type": "point"}]}}, "cameras": [{"type": "orthographic", "orthographic": )"
           R"({"xmag": )" +
           ymag + R"(, "ymag": )" + ymag +
           R"(, "znear": 0.1, "zfar": 100}}], "scenes": [{"nodes": [0, 1]}], "nodes": [)"
           R"({"extensions": {"KHR_lights_punctual": {"light": 0}}}, )"
           R"({"camera": 0, "translation": [0, 0, 5]}]})";
  };
  for (const std::string ymag : {"1e25", "1e19", "1000001"}) {
    const std::string file = path("far.gltf");
    { std::ofstream(file) << with_ymag(ymag); }
    const CommandRun r = run_levrt({"render", "--scene", file, "--width", "8", "--height", "8",
                                    "--out", path("x.png"), "--stats", path("s.json")});
    expect_refused_without_output(r, file, "cameras[0].orthographic.ymag: ");
  }
  const std::string file = path("limit.gltf");
  { std::ofstream(file) << with_ymag("1e6"); }
  const CommandRun r = run_levrt(
      {"render", "--scene", file, "--width", "64", "--height", "1", "--out", path("x.png")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("x.png")));
}

// A file without a camera whose mesh stands at 1e7: the view levrt would frame it from cannot
// stand where coordinates may (1e6). The one line said "scene: /camera/position: coordinate
// magnitude above 1e+06", a camera the file does not have; it now names the missing camera and
// how far the meshes reach. A triangle reaching 1e30 (or infinity) itself is named at its
// POSITION attribute, whatever the camera.
TEST_F(GltfCli, MeshesTooFarToFrameAreNamedNotTheCameraLevrtWouldMake) {
  const std::vector<float> unit = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  for (const float far : {0.0f, 1e30f, std::numeric_limits<float>::infinity()}) {
    std::vector<float> corners = unit;
    if (far != 0.0f) corners[3] = far;
    std::string bytes(reinterpret_cast<const char*>(corners.data()), 36);
    { std::ofstream(path("tri.bin"), std::ios::binary) << bytes; }
    const std::string file = path("far.gltf");
    {
      const std::string node =
          far == 0.0f ? R"({"mesh": 0, "translation": [1e7, 0, 0]})" : R"({"mesh": 0})";
      std::ofstream(file) << levrt_test::gltf_document(
          levrt_test::triangle_buffers("tri.bin") +
          R"(,
        "nodes": [)" +
          node + R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}])");
    }
    const CommandRun r = run_levrt({"render", "--scene", file, "--width", "8", "--height", "8",
                                    "--out", path("x.png"), "--stats", path("s.json")});
    expect_refused_without_output(
        r, file,
        far == 0.0f ? "camera: none in the file, and its meshes and lights"
                    : "meshes[0].primitives[0].attributes.POSITION: element 1 is");
    EXPECT_EQ(r.output.find("/camera/position"), std::string::npos) << r.output;
  }
}

TEST_F(GltfCli, AFileWithNothingToRenderShowsTheBackgroundWithOneWarning) {
  const std::string file = path("empty.gltf");
  {
    std::ofstream(file) << R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12,
      "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}],
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

// Every file of a folder with its size and modification time: what "nothing changed" compares.
std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> folder_state(
    const fs::path& folder) {
  std::map<std::string, std::pair<std::uintmax_t, fs::file_time_type>> state;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const fs::file_status status = fs::symlink_status(entry.path());
    state[entry.path().filename().string()] = {
        fs::is_regular_file(status) ? fs::file_size(entry.path()) : 0,
        fs::is_regular_file(status) ? fs::last_write_time(entry.path()) : fs::file_time_type{}};
  }
  return state;
}

// The hostile glTF classes (docs/extremes.md) through `render`: each file is refused with one line
// naming it and the limit or the glTF path, exit 2, under 256 MB of peak memory (measured by
// /usr/bin/time), within 20 s (a FIFO that blocked would be killed by timeout, exit 124), and
// nothing is written or changed.
TEST_F(GltfCli, HostileFilesExitTwoWithOneLineInLittleMemoryAndChangeNothing) {
  using levrt_test::gltf_document;
  using levrt_test::triangle_buffers;
  const std::string mesh = R"(, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}])";
  levrt_test::write_file(dir_ / "zeros.png", levrt_test::zero_png(8000, 8000));
  levrt_test::write_file(dir_ / "big.bin", "");
  fs::resize_file(dir_ / "big.bin", 1'500'000'000);  // sparse
  ASSERT_EQ(::mkfifo(path("pipe.bin").c_str(), 0600), 0);
  fs::create_directory(dir_ / "inner");
  levrt_test::write_file(dir_ / "secret.bin", std::string(36, 'x'));
  std::string textures, materials, primitives;
  for (int i = 0; i < 16; ++i) {
    const std::string n = std::to_string(i), comma = i > 0 ? ", " : "";
    textures += comma + R"({"source": 0})";
    materials += comma + R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": )" + n + "}}}";
    primitives += comma + R"({"attributes": {"POSITION": 0}, "material": )" + n + "}";
  }
  struct Case {
    std::string name, text, problem;
  };
  const std::vector<Case> cases = {
      {"deep.gltf",
       gltf_document(R"("extras": )" + std::string(30000, '[') + std::string(30000, ']') +
                     R"(, "nodes": [{}])"),
       "nested deeper than 256 levels"},
      {"bomb.gltf",
       gltf_document(triangle_buffers() + R"(, "images": [{"uri": "zeros.png"}], "textures": [)" +
                     textures + R"(], "materials": [)" + materials +
                     R"(], "meshes": [{"primitives": [)" + primitives +
                     R"(]}], "nodes": [{"mesh": 0}])"),
       "textures[0] (images[0], 8000x8000 texels as decoded)"},
      {"zeros.gltf", gltf_document(R"("accessors": [{"componentType": 5126, "type": "VEC3",
           "count": 30000000}])" + mesh),
       "memory budget of 1024 MiB"},
      {"big.gltf", gltf_document(triangle_buffers("big.bin", 1'500'000'000) + mesh),
       "buffers[0].uri 'big.bin': 1500000000 bytes"},
      {"escape.gltf", gltf_document(triangle_buffers("%2e%2e/secret.bin") + mesh),
       "leads outside the scene's folder"},
      {"inner/up.gltf", gltf_document(triangle_buffers("../secret.bin") + mesh),
       "buffers[0].uri: '../secret.bin' (leads outside the scene's folder)"},
      {"fifo.gltf", gltf_document(triangle_buffers("pipe.bin") + mesh), "not a regular file"},
      {"dot.gltf", gltf_document(triangle_buffers(".") + mesh), "names a folder"},
      {"wrap.gltf",
       gltf_document(R"("extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}},
           "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 4294967296}}}])"),
       "nodes[0].extensions.KHR_lights_punctual.light: 4294967296"},
  };
  for (const Case& c : cases) {
    const std::string file = path(c.name);
    levrt_test::write_file(file, c.text);
    const auto before = folder_state(dir_);
    const CommandRun r = levrt_test::run_shell(
        "timeout 20 /usr/bin/time -f %M -o " + levrt_test::shell_quote(path("peak_kb")) + " " +
        LEVRT_BINARY + " render --scene " + levrt_test::shell_quote(file) +
        " --width 8 --height 8 --out " + levrt_test::shell_quote(path("x.png")) + " --stats " +
        levrt_test::shell_quote(path("s.json")));
    expect_refused_without_output(r, file, c.problem);
    // GNU time writes "Command exited with non-zero status 2" first, then the figure.
    std::ifstream peak(path("peak_kb"));
    long peak_kb = 0;
    for (std::string line; std::getline(peak, line);) {
      if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos)
        peak_kb = std::stol(line);
    }
    fs::remove(path("peak_kb"));
    EXPECT_GT(peak_kb, 0) << c.name;
#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer's shadow memory is not the reader's
    EXPECT_LT(peak_kb, 256 * 1024) << c.name << ": peak memory in KB";
#endif
    EXPECT_EQ(folder_state(dir_), before) << c.name;
  }
}

// A chain of 10,000 nodes (the reader recursed per node and overflowed its stack) renders.
TEST_F(GltfCli, TenThousandNestedNodesRender) {
  std::string nodes;
  for (int i = 0; i < 10000; ++i) {
    nodes += std::string(i > 0 ? ", " : "") +
             (i + 1 < 10000 ? R"({"children": [)" + std::to_string(i + 1) + "]}"
                            : R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})");
  }
  const std::string file = path("tall.gltf");
  levrt_test::write_file(file, levrt_test::gltf_document(
                                   R"("extensions": {"KHR_lights_punctual": {"lights":
                                       [{"type": "point"}]}}, "nodes": [)" +
                                   nodes + "]"));
  const CommandRun r = run_levrt(
      {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("x.png")));
}

// Out of memory while loading (here under `ulimit -v`, in tinygltf's JSON parser of a 40 MB data
// URI and in the decoding of a 4096x4096 texture) is one line and exit 1: not abort's two lines
// and exit 134, nor exit 2 as if the file were bad.
TEST_F(GltfCli, OutOfMemoryWhileLoadingIsOneLineAndExitOne) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than any limit lets through";
#else
  const std::string buffer_uri =
      "data:application/octet-stream;base64," + std::string(40'000'000, 'A');
  levrt_test::write_file(dir_ / "embedded.gltf",
                         levrt_test::gltf_document(levrt_test::triangle_buffers(buffer_uri, 36) +
                                                   R"(, "nodes": [{"mesh": 0}], "meshes":
                             [{"primitives": [{"attributes": {"POSITION": 0}}]}])"));
  levrt_test::write_file(dir_ / "big.png", levrt_test::zero_png(4096, 4096));
  levrt_test::write_file(dir_ / "textured.gltf",
                         levrt_test::gltf_document(levrt_test::triangle_buffers() + R"(,
      "images": [{"uri": "big.png"}], "textures": [{"source": 0}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "nodes": [{"mesh": 0}])"));
  for (const std::string name : {"embedded.gltf", "textured.gltf"}) {
    const CommandRun r = levrt_test::run_shell(
        "ulimit -v 150000 && " + std::string(LEVRT_BINARY) + " render --scene " +
        levrt_test::shell_quote(path(name)) + " --width 8 --height 8 --out " +
        levrt_test::shell_quote(path("x.png")));
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.output;
    EXPECT_EQ(r.output.rfind("levrt: error: ", 0), 0u) << name << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << name << ": " << r.output;
    EXPECT_FALSE(fs::exists(path("x.png"))) << name;
  }
#endif
}

}  // namespace
