// The display step from the command line: --exposure and --display, their defaults per kind of
// scene, what the statistics record, and that linear at EV 0 leaves today's images as they were.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/output_files.h"
#include "app/render_command.h"
#include "app/scene_loading.h"
#include "renderer/framebuffer.h"
#include "tests/support/folder_test.h"
#include "tests/support/gltf_files.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::read_file;
using levrt_test::run_levrt;

class DisplayCli : public levrt_test::FolderTest {};

// The PNG `levrt render` writes for building, maze, hall and a scene file at their defaults is the
// PNG of the framebuffer's 8-bit image with no display step at all (framebuffer_rgb8): the
// display step at linear, EV 0 changes no bit.
TEST_F(DisplayCli, LinearAtExposureZeroIsTodaysImageBitForBit) {
  const std::string scene_file = path("maze2.json");
  ASSERT_EQ(run_levrt({"export", "--scene", "maze", "--level", "2", "--out", scene_file}).exit_code,
            0);
  for (const std::string scene : {"building", "maze", "hall", scene_file.c_str()}) {
    const std::string out = path("image.png"), stats = path("stats.json");
    const CommandRun r = run_levrt({"render", "--scene", scene, "--width", "64", "--height", "48",
                                    "--out", out, "--stats", stats, "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    app::Settings settings;
    settings.scene.name = scene;
    settings.image.width = 64;
    settings.image.height = 48;
    const std::unique_ptr<app::LoadedScene> loaded = app::load_scene(settings.scene);
    const renderer::RenderResult result =
        app::render_image(*loaded, settings, settings.method.method);
    EXPECT_EQ(read_file(out),
              app::png_rgb8_bytes(64, 48, renderer::framebuffer_rgb8(result.framebuffer)))
        << scene;
    const auto json = nlohmann::json::parse(read_file(stats));
    EXPECT_EQ(json["exposure_ev"], 0.0) << scene;
    EXPECT_EQ(json["exposure_auto"], false) << scene;
    EXPECT_EQ(json["display"], "linear") << scene;
  }
}

TEST_F(DisplayCli, ExposureAndDisplayChangeTheImageAndAreRecorded) {
  const std::string plain = path("plain.png"), bright = path("bright.png"), stats = path("s.json");
  const std::vector<std::string> base = {"render", "--width", "32", "--height", "24", "--quiet"};
  auto args = base;
  args.insert(args.end(), {"--out", plain});
  ASSERT_EQ(run_levrt(args).exit_code, 0);
  args = base;
  args.insert(args.end(),
              {"--out", bright, "--exposure", "1.5", "--display", "srgb", "--stats", stats});
  ASSERT_EQ(run_levrt(args).exit_code, 0);
  EXPECT_NE(read_file(plain), read_file(bright));
  const auto json = nlohmann::json::parse(read_file(stats));
  EXPECT_EQ(json["exposure_ev"], 1.5);
  EXPECT_EQ(json["exposure_auto"], false);
  EXPECT_EQ(json["display"], "srgb");
}

// A glTF file opens at auto and neutral; the EV auto chose is what the statistics record, and
// typed flags win over the defaults.
TEST_F(DisplayCli, GltfDefaultsToAutoAndNeutral) {
  const fs::path gltf = dir_ / "triangle.gltf";
  levrt_test::write_file(gltf, levrt_test::triangle_scene());
  const std::string stats = path("s.json");
  ASSERT_EQ(run_levrt({"render", "--scene", gltf.string(), "--width", "16", "--height", "12",
                       "--stats", stats, "--quiet"})
                .exit_code,
            0);
  auto json = nlohmann::json::parse(read_file(stats));
  EXPECT_EQ(json["exposure_auto"], true);
  EXPECT_EQ(json["display"], "neutral");
  ASSERT_EQ(run_levrt({"render", "--scene", gltf.string(), "--width", "16", "--height", "12",
                       "--stats", stats, "--quiet", "--exposure", "-2", "--display", "linear"})
                .exit_code,
            0);
  json = nlohmann::json::parse(read_file(stats));
  EXPECT_EQ(json["exposure_auto"], false);
  EXPECT_EQ(json["exposure_ev"], -2.0);
  EXPECT_EQ(json["display"], "linear");
}

TEST_F(DisplayCli, BadExposureOrDisplayIsOneLineExitTwo) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"--exposure", {"", "x", "nan", "inf", "65", "-64.5", "Auto", "auto2", "1ev"}},
      {"--display", {"", "aces", "sRGB", "filmic"}},
  };
  const std::string out = path("image.png");
  for (const auto& [flag, values] : cases) {
    for (const std::string& value : values) {
      const CommandRun r =
          run_levrt({"render", flag, value, "--width", "8", "--height", "8", "--out", out});
      const std::string label = flag + " '" + value + "': " + r.output;
      EXPECT_EQ(r.exit_code, 2) << label;
      EXPECT_NE(r.output.find(flag), std::string::npos) << label;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << label;
      EXPECT_FALSE(fs::exists(out)) << label;
    }
  }
}

}  // namespace
