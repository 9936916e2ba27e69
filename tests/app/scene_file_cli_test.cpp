// `levrt export` and `--scene FILE.json` through the binary: a file exported from a model
// renders the same PNG bytes; a bad file is one line and exit code 2, with nothing written.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
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

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class SceneFileCli : public levrt_test::FolderTest {
 protected:
  // A glTF of one point light whose file name is Latin-1 ("l\xe9.gltf": not UTF-8); its path.
  std::string write_latin1_named_gltf() {
    const std::string gltf = path("l\xe9.gltf");
    levrt_test::write_file(gltf, levrt_test::gltf_document(R"("nodes": [{"translation": [0, 0, 1],
        "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5}]}})"));
    return gltf;
  }
};

TEST_F(SceneFileCli, ExportedFileRendersTheSamePngAndHierarchy) {
  for (const std::string scene : {"building", "maze", "hall"}) {
    const std::string file = path(scene + ".json");
    const CommandRun e = run_levrt({"export", "--scene", scene, "--level", "4", "--out", file});
    ASSERT_EQ(e.exit_code, 0) << e.output;
    const std::vector<std::string> common = {"--width", "40", "--height", "30", "--method", "lev"};
    std::vector<std::string> a = {"render", "--scene",     scene,     "--level",     "4",
                                  "--out",  path("a.png"), "--stats", path("a.json")};
    std::vector<std::string> b = {"render",      "--scene", file,          "--out",
                                  path("b.png"), "--stats", path("b.json")};
    a.insert(a.end(), common.begin(), common.end());
    b.insert(b.end(), common.begin(), common.end());
    ASSERT_EQ(run_levrt(a).exit_code, 0);
    const CommandRun rb = run_levrt(b);
    ASSERT_EQ(rb.exit_code, 0) << rb.output;
    EXPECT_EQ(read_file(path("a.png")), read_file(path("b.png"))) << scene;
    const std::string sa = read_file(path("a.json")), sb = read_file(path("b.json"));
    const auto bytes = [](const std::string& stats) {
      const std::size_t at = stats.find("\"hierarchy_bytes\"");
      return stats.substr(at, stats.find(',', at) - at);
    };
    EXPECT_EQ(bytes(sa), bytes(sb)) << scene;
    EXPECT_NE(sb.find("\"scene\": \"" + scene + "\""), std::string::npos) << sb;
  }
}

TEST_F(SceneFileCli, BadFilesExitTwoWithOneLineAndNoOutput) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"levrt_scene\": 1, \"camera\": {\"position\": [0, 0, 5], \"target\": [0, 0, 0], \"up\": "
       "[0, 1, 0]}, "
       "\"root\": {\"type\": \"sphere\", \"material\": \"x\", \"centre\": [0, 0, 0], \"radius\": "
       "1}}",
       "/root/material: no material named 'x'"},
      {"{\"levrt_scene\": 1, \"root\": {\"type\": \"union\", \"children\": []}}",
       "/camera: missing"},
      {"{\"levrt_scene\": 1,", "invalid JSON"},
  };
  for (const auto& [text, problem] : cases) {
    const std::string file = path("bad.json");
    { std::ofstream(file) << text; }
    const CommandRun r = run_levrt(
        {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(file + ": "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
  const CommandRun missing =
      run_levrt({"render", "--scene", path("none.json"), "--out", path("x.png")});
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

// A scene file's orthographic half height is bounded like any length (1e6): rays start up to it
// (times the aspect ratio) from the camera, and Embree aborts on ray origins past about 1.8e18
// (1e30 was exit 134). The limit itself renders.
TEST_F(SceneFileCli, AHugeOrthographicHalfHeightIsRefusedAndTheLimitRenders) {
  const auto scene = [](const std::string& half_height) {
    return R"({"levrt_scene": 1, "camera": {"position": [0, -10, 5], "target": [0, 0, 0], )"
           R"("orthographic_half_height": )" +
           half_height +
           R"(}, "materials": [{"name": "m"}], "root": {"type": "union", "children": [)"
           R"({"type": "sphere", "material": "m", "centre": [0, 0, 0], "radius": 1}, )"
           R"({"type": "affine", "translate": [0, 0, 4], "child": )"
           R"({"type": "point_light", "intensity": [1, 1, 1]}}]}})";
  };
  const std::string file = path("ortho.json");
  for (const std::string half_height : {"1e30", "1e19", "1000001"}) {
    { std::ofstream(file) << scene(half_height); }
    const CommandRun r = run_levrt(
        {"render", "--scene", file, "--width", "8", "--height", "8", "--out", path("x.png")});
    EXPECT_EQ(r.exit_code, 2) << half_height << ": " << r.output;
    EXPECT_NE(r.output.find(file + ": /camera/orthographic_half_height: "), std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
  { std::ofstream(file) << scene("1e6"); }
  const CommandRun r = run_levrt(
      {"render", "--scene", file, "--width", "64", "--height", "1", "--out", path("x.png")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("x.png")));
}

// `export --out ''` names no file: one line and exit 2, as render's outputs do (it was exit 1,
// "cannot rename into place", after the scene was built).
TEST_F(SceneFileCli, ExportToAnEmptyNameIsRefusedWithOneLine) {
  const CommandRun r = run_levrt({"export", "--scene", "maze", "--level", "1", "--out", ""});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--out: needs a file name, got ''"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

// A glTF's meshes cannot be written to a scene file: the one line names the glTF (it named only
// "/root", a path of no file the user gave).
TEST_F(SceneFileCli, ExportOfAGltfWithMeshesNamesTheFile) {
  const std::string file = path("triangle.gltf");
  { std::ofstream(file) << levrt_test::triangle_scene(); }
  const CommandRun r = run_levrt({"export", "--scene", file, "--out", path("out.json")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("levrt: " + file + ": /root: triangle meshes", 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(path("out.json")));
}

TEST_F(SceneFileCli, LevelsAndLightCountsBelongToModels) {
  const std::string file = path("maze.json");
  ASSERT_EQ(run_levrt({"export", "--scene", "maze", "--lights", "189", "--out", file}).exit_code,
            0);
  const CommandRun level =
      run_levrt({"render", "--scene", file, "--level", "2", "--out", path("x.png")});
  EXPECT_EQ(level.exit_code, 2) << level.output;
  EXPECT_NE(level.output.find("--level"), std::string::npos) << level.output;
  const CommandRun lights =
      run_levrt({"render", "--scene", file, "--lights", "189", "--out", path("x.png")});
  EXPECT_EQ(lights.exit_code, 2) << lights.output;
  EXPECT_NE(lights.output.find("--lights"), std::string::npos) << lights.output;
  const CommandRun model =
      run_levrt({"render", "--scene", "maze", "--lights", "64", "--out", path("x.png")});
  EXPECT_EQ(model.exit_code, 2) << model.output;
  EXPECT_NE(model.output.find("45, 189, 765, 3069, 12285"), std::string::npos) << model.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(SceneFileCli, ExportRefusesBadArgumentsAndWritesNothing) {
  const std::vector<std::vector<std::string>> cases = {
      {"export", "--scene", "maze", "--out", path("missing/m.json")},
      {"export", "--scene", "castle", "--out", path("m.json")},
      {"export", "--scene", "hall", "--level", "2", "--out", path("m.json")},
      {"export", "--scene", "hall"},
      {"export", "--scene", "hall", "--level", "3", "--lights", "64", "--out", path("m.json")},
  };
  for (const auto& args : cases) {
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_TRUE(fs::is_empty(dir_)) << r.output;
  }
}

// A glTF whose file name is not UTF-8 (Latin-1 'é') is named by that stem: the scene file
// written holds the name with U+FFFD for the invalid byte, and renders. Before: exit 1 with
// nlohmann's "incomplete UTF-8 string".
TEST_F(SceneFileCli, ExportOfAGltfWhoseFileNameIsNotUtf8WritesAValidSceneFile) {
  const std::string gltf = write_latin1_named_gltf();
  const CommandRun r = run_levrt({"export", "--scene", gltf, "--out", path("lights.json")});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(path("lights.json")).find("\"name\": \"l\xef\xbf\xbd\""), std::string::npos)
      << read_file(path("lights.json"));
  EXPECT_EQ(run_levrt({"render", "--scene", path("lights.json"), "--width", "8", "--height", "8",
                       "--out", path("lights.png")})
                .exit_code,
            0);
}

// The stats of a render name the scene; a glTF whose file name is not UTF-8 (Latin-1) is named
// with U+FFFD for its invalid byte, as export writes it, instead of failing after the render.
TEST_F(SceneFileCli, RenderStatsOfAGltfWhoseFileNameIsNotUtf8AreWritten) {
  const std::string gltf = write_latin1_named_gltf();
  const CommandRun r = run_levrt({"render", "--scene", gltf, "--width", "8", "--height", "8",
                                  "--out", path("l.png"), "--stats", path("l.json")});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(path("l.json")).find("l\xef\xbf\xbd"), std::string::npos)
      << read_file(path("l.json"));
  EXPECT_TRUE(fs::exists(path("l.png")));
}

// A scene file has the level it was exported at: `export --level` with one is refused, as
// `render --level` is, instead of being ignored.
TEST_F(SceneFileCli, ExportOfASceneFileRefusesALevel) {
  ASSERT_EQ(run_levrt({"export", "--scene", "maze", "--out", path("m.json")}).exit_code, 0);
  const CommandRun r =
      run_levrt({"export", "--scene", path("m.json"), "--level", "3", "--out", path("n.json")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("--level: a scene file has no levels, got '3'"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(path("n.json")));
}

}  // namespace
