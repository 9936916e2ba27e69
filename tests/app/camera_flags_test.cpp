// The camera flags (app/camera_flags.h): parsing and refusing each flag, replacing parts of the
// preset, the copied text reading back as the same floats, and through `levrt render`: a moved
// camera changes the image, --camera-from a stats file renders that image again byte for byte,
// every bad value is one line naming the flag (exit 2), and no output may replace the camera file.
#include "app/camera_flags.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "tests/support/folder_test.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {
namespace fs = std::filesystem;
using app::CameraFlags;
using app::CameraFlagTexts;
using levrt_test::CommandRun;
using levrt_test::read_file;
using levrt_test::run_levrt;

// The message of the UsageError parsing throws, or "" when it parses.
std::string refusal(const CameraFlagTexts& texts) {
  try {
    app::parse_camera_flags(texts);
  } catch (const app::UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(CameraFlags, ParseEachFlagAndRefuseBadValuesNamingTheFlag) {
  CameraFlagTexts texts;
  texts.position = "1,-2.5,3e1";
  texts.fov_deg = "30";
  const CameraFlags flags = app::parse_camera_flags(texts);
  EXPECT_EQ(*flags.position, glm::vec3(1.0f, -2.5f, 30.0f));
  EXPECT_EQ(*flags.vertical_fov_deg, 30.0f);
  EXPECT_FALSE(flags.target.has_value());
  EXPECT_TRUE(app::parse_camera_flags({}).empty());

  for (const std::string bad : {"1,2", "1,2,3,4", "1,,3", "a,b,c", "nan,0,0", "inf,0,0", "1e39,0,0",
                                " 1,2,3", "1,2,3 ", ",,", ""}) {
    if (bad.empty()) continue;  // an empty text is a flag not given
    CameraFlagTexts t;
    t.target = bad;
    const std::string message = refusal(t);
    EXPECT_EQ(message.rfind("--camera-target: must be X,Y,Z", 0), 0u) << bad << ": " << message;
    EXPECT_NE(message.find("'" + bad + "'"), std::string::npos) << message;
  }
  for (const std::string bad : {"0", "180", "-5", "200", "x", "nan", "45deg"}) {
    CameraFlagTexts t;
    t.fov_deg = bad;
    EXPECT_EQ(refusal(t).rfind("--fov: must be a decimal number of degrees in (0, 180)", 0), 0u)
        << bad;
  }
}

TEST(CameraFlags, ReplacePartsOfThePresetAndRefuseAViewOfNothing) {
  renderer::Camera preset;
  preset.position = {0.0f, -10.0f, 5.0f};
  preset.target = {0.0f, 0.0f, 0.0f};
  CameraFlags flags;
  flags.vertical_fov_deg = 20.0f;
  const renderer::Camera narrow = app::apply_camera_flags(preset, flags, glm::vec3(0.0f));
  EXPECT_EQ(narrow.position, preset.position);
  EXPECT_EQ(narrow.target, preset.target);
  EXPECT_EQ(narrow.vertical_fov_deg, 20.0f);

  CameraFlags at_target;
  at_target.position = preset.target;
  EXPECT_THROW(app::apply_camera_flags(preset, at_target, glm::vec3(0.0f)), app::UsageError);
  CameraFlags up_along_view;
  up_along_view.up = glm::vec3(0.0f, 10.0f, -5.0f);
  EXPECT_THROW(app::apply_camera_flags(preset, up_along_view, glm::vec3(0.0f)), app::UsageError);
}

TEST(CameraFlags, TheCopiedTextReadsBackAsTheSameCamera) {
  renderer::Camera c;
  c.position = {0.1f, -1.0f / 3.0f, 123456.789f};
  c.target = {1e-40f, 2.0f, -0.3f};  // a subnormal reads back too
  c.up = {0.0f, 0.0f, 1.0f};
  c.vertical_fov_deg = 37.123456f;
  const std::string text = app::camera_flags_text(c);
  // "--camera-position X --camera-target Y --camera-up Z --fov W"
  std::vector<std::string> words;
  std::size_t start = 0;
  for (std::size_t space = text.find(' ');; space = text.find(' ', start)) {
    words.push_back(text.substr(start, space == std::string::npos ? space : space - start));
    if (space == std::string::npos) break;
    start = space + 1;
  }
  ASSERT_EQ(words.size(), 8u) << text;
  EXPECT_EQ(words[0], "--camera-position");
  CameraFlagTexts texts;
  texts.position = words[1];
  texts.target = words[3];
  texts.up = words[5];
  texts.fov_deg = words[7];
  const renderer::Camera back =
      app::apply_camera_flags(renderer::Camera{}, app::parse_camera_flags(texts), glm::vec3(0.0f));
  EXPECT_EQ(back.position, c.position);
  EXPECT_EQ(back.target, c.target);
  EXPECT_EQ(back.up, c.up);
  EXPECT_EQ(back.vertical_fov_deg, c.vertical_fov_deg);
}

class CameraCli : public levrt_test::FolderTest {
 protected:
  CommandRun render(std::vector<std::string> args) const {
    for (const std::string a : {"--lights", "64", "--width", "48", "--height", "36", "--quiet"})
      args.push_back(a);
    args.insert(args.begin(), "render");
    return run_levrt(args);
  }
  // Each render with these flags is refused: exit 2, one line holding the text, no image.
  void expect_each_refused(
      const std::vector<std::pair<std::vector<std::string>, std::string>>& cases) const {
    for (const auto& [flags, expected] : cases) {
      std::vector<std::string> args = flags;
      args.push_back("--out");
      args.push_back(path("out.png"));
      const CommandRun r = render(args);
      EXPECT_EQ(r.exit_code, 2) << flags[0] << " " << flags[1] << ": " << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
      EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
      EXPECT_FALSE(fs::exists(path("out.png"))) << r.output;
    }
  }
};

TEST_F(CameraCli, AMovedCameraIsRecordedAndRendersAgainFromItsStats) {
  ASSERT_EQ(render({"--out", path("preset.png")}).exit_code, 0);
  const CommandRun moved =
      render({"--camera-position", "2,-14,7", "--camera-target", "0.5,0,1", "--fov", "35", "--out",
              path("moved.png"), "--stats", path("moved.json")});
  ASSERT_EQ(moved.exit_code, 0) << moved.output;
  EXPECT_NE(read_file(path("moved.png")), read_file(path("preset.png")));
  const nlohmann::json stats = nlohmann::json::parse(read_file(path("moved.json")));
  EXPECT_EQ(stats["camera"]["position"], nlohmann::json::array({2.0, -14.0, 7.0}));
  EXPECT_EQ(stats["camera"]["target"], nlohmann::json::array({0.5, 0.0, 1.0}));
  EXPECT_EQ(stats["camera"]["vertical_fov_deg"], 35.0);

  const CommandRun again =
      render({"--camera-from", path("moved.json"), "--out", path("again.png")});
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_file(path("again.png")), read_file(path("moved.png")));
  // A flag given with --camera-from overrides that part.
  ASSERT_EQ(render({"--camera-from", path("moved.json"), "--fov", "50", "--out", path("wide.png")})
                .exit_code,
            0);
  EXPECT_NE(read_file(path("wide.png")), read_file(path("moved.png")));
}

TEST_F(CameraCli, AnOrthographicCameraIsRecordedCopiedAndRendersAgainFromItsStats) {
  const CommandRun ortho = render(
      {"--ortho-half-height", "6", "--out", path("ortho.png"), "--stats", path("ortho.json")});
  ASSERT_EQ(ortho.exit_code, 0) << ortho.output;
  ASSERT_EQ(render({"--out", path("preset.png")}).exit_code, 0);
  EXPECT_NE(read_file(path("ortho.png")), read_file(path("preset.png")));
  const nlohmann::json stats = nlohmann::json::parse(read_file(path("ortho.json")));
  EXPECT_EQ(stats["camera"]["orthographic_half_height"], 6.0);
  const CommandRun again =
      render({"--camera-from", path("ortho.json"), "--out", path("again.png")});
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_file(path("again.png")), read_file(path("ortho.png")));
  // --fov over it is perspective again: the preset's image.
  ASSERT_EQ(render({"--camera-from", path("ortho.json"), "--fov", "45", "--out", path("p.png")})
                .exit_code,
            0);
  EXPECT_EQ(read_file(path("p.png")), read_file(path("preset.png")));

  renderer::Camera camera;
  camera.orthographic_half_height = 0.3f;
  const std::string text = app::camera_flags_text(camera);
  EXPECT_NE(text.find(" --ortho-half-height 0.300000012"), std::string::npos) << text;
  EXPECT_EQ(text.find("--fov"), std::string::npos) << text;
  CameraFlagTexts both;
  both.fov_deg = "30";
  both.ortho_half_height = "2";
  EXPECT_EQ(refusal(both).rfind("--ortho-half-height: ", 0), 0u) << refusal(both);
  CameraFlagTexts zero;
  zero.ortho_half_height = "0";
  EXPECT_EQ(refusal(zero).rfind("--ortho-half-height: must be a positive number", 0), 0u);
}

TEST_F(CameraCli, BadCamerasExitTwoWithOneLineNamingTheFlagAndWriteNothing) {
  std::ofstream(path("no_camera.json")) << R"({"scene": "building"})";
  std::ofstream(path("bad_fov.json"))
      << R"({"camera": {"position": [0,-10,5], "target": [0,0,0], "up": [0,0,1], )"
         R"("vertical_fov_deg": 0}})";
  std::ofstream(path("text.json")) << "not json";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--camera-position", "1,2"}, "--camera-position"},
      {{"--camera-up", "nan,0,1"}, "--camera-up"},
      {{"--fov", "0"}, "--fov"},
      {{"--ortho-half-height", "0"}, "--ortho-half-height"},
      {{"--ortho-half-height", "-1"}, "--ortho-half-height"},
      {{"--ortho-half-height", "nan"}, "--ortho-half-height"},
      {{"--ortho-half-height", "2", "--fov", "40"}, "not both"},
      {{"--camera-position", "1,1,1", "--camera-target", "1,1,1"}, "--camera-target"},
      {{"--camera-from", path("missing.json")}, "--camera-from"},
      {{"--camera-from", dir_.string()}, "--camera-from"},
      {{"--camera-from", path("no_camera.json")}, "no \"camera\" object"},
      {{"--camera-from", path("bad_fov.json")}, "camera.vertical_fov_deg"},
      {{"--camera-from", path("text.json")}, "not JSON"},
  };
  expect_each_refused(cases);
}

// A camera position, target or orthographic half height past a scene's coordinates (1e6) is
// refused naming the flag: rays start there, and Embree aborts on ray origins past about 1.8e18
// (--camera-position 1e30,1e30,1e30 and --ortho-half-height 1e19 were exit 134). So is a stats
// file carrying such a camera. The limit itself renders; up is a direction, any size.
TEST_F(CameraCli, FarCamerasAreRefusedNamingTheFlagAndTheLimitRenders) {
  std::ofstream(path("far.json"))
      << R"({"camera": {"position": [1e30, 1e30, 1e30], "target": [0,0,0], "up": [0,0,1], )"
         R"("vertical_fov_deg": 40}})";
  std::ofstream(path("wide.json"))
      << R"({"camera": {"position": [0,-10,5], "target": [0,0,0], "up": [0,0,1], )"
         R"("vertical_fov_deg": 40, "orthographic_half_height": 1e19}})";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--camera-position", "1e30,1e30,1e30"}, "--camera-position: must be X,Y,Z"},
      {{"--camera-position", "0,0,1000001"}, "--camera-position: must be X,Y,Z"},
      {{"--camera-target", "1e30,0,0"}, "--camera-target: must be X,Y,Z"},
      {{"--ortho-half-height", "1e19"}, "--ortho-half-height: must be a positive number"},
      {{"--ortho-half-height", "1e30"}, "--ortho-half-height: must be a positive number"},
      {{"--camera-from", path("far.json")}, "camera.position: magnitude above 1000000"},
      {{"--camera-from", path("wide.json")}, "camera.orthographic_half_height: must be"},
  };
  expect_each_refused(cases);
  const CommandRun limit =
      render({"--camera-position", "1e6,-1e6,1e6", "--camera-target", "0,0,0", "--camera-up",
              "1e30,0,1e30", "--ortho-half-height", "1e6", "--out", path("out.png")});
  EXPECT_EQ(limit.exit_code, 0) << limit.output;
  EXPECT_TRUE(fs::exists(path("out.png")));
}

// A camera whose frame exists in the main thread's float mode but not in the render threads'
// (denormals flushed to zero): an up of 1e-38, a target 1e-38 from the position. Refused like
// the scene file's camera; before, a release build rendered the background alone (exit 0, no
// shading point) and a checked build aborted on a ray with no direction.
TEST_F(CameraCli, ACameraDegenerateInTheRenderFloatModeIsRefused) {
  // Each named by the flag that moved the camera (the up alone was blamed on --camera-target).
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--camera-up", "1e-38,0,0"}, "--camera-up"},
      {{"--camera-up", "0,1,-1.0379746835443038"}, "--camera-up"},  // along the preset's view
      {{"--camera-position", "40,37.6,0"}, "--camera-position"},    // at the preset's target
      {{"--camera-position", "0,0,0", "--camera-target", "1e-38,0,0"}, "--camera-target"},
  };
  for (const auto& [flags, named] : cases) {
    std::vector<std::string> args = flags;
    args.push_back("--out");
    args.push_back(path("out.png"));
    const CommandRun r = render(args);
    EXPECT_EQ(r.exit_code, 2) << flags[1] << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(r.output.rfind("levrt: " + named + ": the camera at", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("has no view"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("out.png"))) << r.output;
  }
  // A tiny up whose frame stays in normal floats is a direction like any other.
  EXPECT_EQ(render({"--camera-up", "1e-30,0,1e-30", "--out", path("out.png")}).exit_code, 0);
}

// A stats file whose camera has no view (its target at its position) is named as the source; the
// refusal blamed --camera-target, a flag not given.
TEST_F(CameraCli, ACameraFileWithoutAViewIsNamedAsTheSource) {
  {
    std::ofstream file(path("flat.json"));
    file << R"({"camera": {"position": [1, 2, 3], "target": [1, 2, 3], "up": [0, 0, 1],)"
         << R"( "vertical_fov_deg": 45}})";
  }
  const CommandRun r = render({"--camera-from", path("flat.json"), "--out", path("out.png")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("--camera-from: " + path("flat.json") + ": the camera at 1,2,3"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("--camera-target"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

// A camera flag given an empty value is refused naming it, not taken as "not given".
TEST_F(CameraCli, AnEmptyCameraFlagIsRefusedNamingIt) {
  for (const std::string flag : {"--camera-position", "--camera-target", "--camera-up", "--fov",
                                 "--ortho-half-height", "--camera-from"}) {
    const CommandRun r = render({flag, "", "--out", path("out.png")});
    EXPECT_EQ(r.exit_code, 2) << flag << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find(flag + ": needs a value, got ''"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("out.png"))) << r.output;
  }
}

TEST_F(CameraCli, NoOutputReplacesTheCameraFile) {
  ASSERT_EQ(render({"--stats", path("s.json")}).exit_code, 0);
  const std::string before = read_file(path("s.json"));
  const CommandRun r = render({"--camera-from", path("s.json"), "--stats", path("s.json")});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--stats"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(path("s.json")), before);
}

// A scene far from the origin is traced moved near it (scenes/render_space.h), but its cameras
// are the file's: the stats report the camera in the file's coordinates, and the flags given
// in them (the file's own camera, or --camera-from those stats) render the same image as the
// preset. Before, the flags were applied in render space and the stats reported it
// ([0, 0.4, -0.4] for a camera at [200040, -25.6, 65.6]).
TEST_F(CameraCli, AFarScenesCameraIsReadAndGivenInTheFilesCoordinates) {
  const std::string far_scene =
      R"({"levrt_scene": 1, "camera": {"position": [200000, -10, 5], "target": [200000, 0, 0], )"
      R"("up": [0, 0, 1], "fov_degrees": 40}, "materials": [{"name": "m"}], )"
      R"("root": {"type": "affine", "translate": [200000, 0, 0], "child": {"type": "union", )"
      R"("children": [{"type": "sphere", "material": "m", "centre": [0, 0, 0], "radius": 1}, )"
      R"({"type": "quad", "material": "m", "corner": [-5, -5, -1], "edge_u": [10, 0, 0], )"
      R"("edge_v": [0, 10, 0]}, {"type": "affine", "translate": [2, -2, 4], "child": )"
      R"({"type": "point_light", "intensity": [20, 20, 20]}}]}}})";
  std::ofstream(path("far.json")) << far_scene;
  const auto render = [&](const std::string& name, std::vector<std::string> flags) {
    std::vector<std::string> args = {"render",
                                     "--scene",
                                     path("far.json"),
                                     "--width",
                                     "32",
                                     "--height",
                                     "24",
                                     "--out",
                                     path(name + ".png"),
                                     "--stats",
                                     path(name + ".json")};
    args.insert(args.end(), flags.begin(), flags.end());
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.output;
    return read_file(path(name + ".png"));
  };
  const std::string preset = render("preset", {});
  const nlohmann::json stats = nlohmann::json::parse(read_file(path("preset.json")));
  EXPECT_EQ(stats["camera"]["position"], nlohmann::json::parse("[200000, -10, 5]"))
      << stats["camera"];
  EXPECT_EQ(stats["camera"]["target"], nlohmann::json::parse("[200000, 0, 0]")) << stats["camera"];
  EXPECT_EQ(render("flags", {"--camera-position", "200000,-10,5", "--camera-target", "200000,0,0"}),
            preset);
  EXPECT_EQ(render("from", {"--camera-from", path("preset.json")}), preset);
  EXPECT_NE(render("moved", {"--camera-position", "200000,-12,5"}), preset);
}

}  // namespace
