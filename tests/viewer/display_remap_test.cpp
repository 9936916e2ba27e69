// The viewer's exposure slider and display switch: under Xvfb, a scripted change of
// `exposure` or `display` re-maps the window's image at once from the radiance the UI holds,
// without a new render: the snapshot statistics before and after show the same render (passes,
// render and refit times), with the new exposure and curve recorded, and the snapshot writes
// the EXR of the radiance beside its PNGs. The method is rt, whose images do not depend on the
// exposure (a method with a tolerance renders again: app::restart_needed). Skipped only when Xvfb
// is missing.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/exr_file.h"
#include "tests/support/folder_test.h"
#include "tests/support/png_file.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/xvfb_server.h"

namespace {

using levrt_test::read_file;
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::have_xvfb;

using RemapPng = levrt_test::PngImage;
using levrt_test::read_png_image;

// Pixels that differ inside the picture (right of the panel, above the statistics).
int picture_differences(const RemapPng& a, const RemapPng& b) {
  int differences = 0;
  for (int y = a.height * 15 / 100; y < a.height * 55 / 100; ++y) {
    for (int x = a.width / 2; x < a.width * 9 / 10; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * a.width + x);
      if (a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2])
        ++differences;
    }
  }
  return differences;
}

// The one file of `folder` whose name ends in `suffix`.
fs::path file_ending(const fs::path& folder, const std::string& suffix) {
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return entry.path();
  }
  return {};
}

class DisplayRemap : public levrt_test::FolderTest {};

TEST_F(DisplayRemap, ExposureAndDisplayReMapTheWindowWithoutANewRender) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const CommandRun r = levrt_test::run_viewer_on_xvfb({
      "--lights", "64",
      "--method", "rt",
      "--width",  "64",
      "--height", "48",
      "--spp",    "2",
      "--window", "800x600",
      "--frames", "9",                                         //
      "--set",    "await=idle@0",                              //
      "--set",    "snapshot=" + path("before") + "@1",         //
      "--set",    "screenshot=" + path("linear.png") + "@2",   //
      "--set",    "exposure=1.5@3",                            //
      "--set",    "screenshot=" + path("exposed.png") + "@4",  //
      "--set",    "display=neutral@5",                         //
      "--set",    "screenshot=" + path("neutral.png") + "@6",  //
      "--set",    "snapshot=" + path("after") + "@7",          //
  });
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RemapPng linear = read_png_image(path("linear.png")),
                 exposed = read_png_image(path("exposed.png")),
                 neutral = read_png_image(path("neutral.png"));
  ASSERT_GT(linear.width, 0);
  EXPECT_GT(picture_differences(linear, exposed), 100);
  EXPECT_GT(picture_differences(exposed, neutral), 100);

  const auto before = nlohmann::json::parse(read_file(file_ending(dir_ / "before", "_stats.json")));
  const auto after = nlohmann::json::parse(read_file(file_ending(dir_ / "after", "_stats.json")));
  EXPECT_EQ(before["exposure_ev"], 0.0);
  EXPECT_EQ(before["display"], "linear");
  EXPECT_EQ(after["exposure_ev"], 1.5);
  EXPECT_EQ(after["display"], "neutral");
  // The same render: no pass was added, none restarted.
  for (const char* key : {"spp", "time_render_s", "time_setup_s", "shading_points"})
    EXPECT_EQ(before[key], after[key]) << key;
  // The snapshot's EXR holds the radiance, the same before and after the re-map.
  const levrt_test::ExrFile exr_before =
      levrt_test::read_exr(read_file(file_ending(dir_ / "before", ".exr")));
  const levrt_test::ExrFile exr_after =
      levrt_test::read_exr(read_file(file_ending(dir_ / "after", ".exr")));
  EXPECT_EQ(exr_before.width, 64);
  EXPECT_EQ(exr_before.channels.at("R"), exr_after.channels.at("R"));
  EXPECT_EQ(exr_before.channels.count("lights_tested"), 1u);
}

// lightcuts goes on at a new exposure (its cut is relative to the point's own total), so the
// window's figures of the render it holds are put at the new exposure: the snapshot's bound and
// noise equal `levrt render`'s at that exposure, not those of the exposure the render was made
// at. (No method that goes on estimates missed light: rt, the samplers and lightcuts leave none
// out; display_image_test checks its figures are re-exposed all the same.)
TEST_F(DisplayRemap, TheFiguresOfARenderThatGoesOnAreThoseOfARenderAtTheNewExposure) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // lightcuts' own cut (its bound is not zero), not rt's loop (renderer/rt_fallback.h).
  const std::vector<std::string> render = {"--lights", "64", "--method",      "lightcuts",
                                           "--width",  "48", "--height",      "36",
                                           "--spp",    "2",  "--rt-fallback", "off"};
  std::vector<std::string> view = render;
  for (const char* a : {"--window", "800x600", "--frames", "6", "--set", "await=idle@0", "--set",
                        "exposure=2@1", "--set", "await=idle@2"})
    view.push_back(a);
  view.push_back("--set");
  view.push_back("snapshot=" + path("after") + "@3");
  const CommandRun r = levrt_test::run_viewer_on_xvfb(view);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto after = nlohmann::json::parse(read_file(file_ending(dir_ / "after", "_stats.json")));
  EXPECT_EQ(after["exposure_ev"], 2.0);

  const auto headless = [&](const char* ev, const std::string& stats) {
    std::vector<std::string> args = {"render"};
    args.insert(args.end(), render.begin(), render.end());
    for (const std::string& a : {std::string("--exposure"), std::string(ev), std::string("--stats"),
                                 path(stats), std::string("--quiet")})
      args.push_back(a);
    const CommandRun run = levrt_test::run_levrt(args);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return nlohmann::json::parse(read_file(path(stats)));
  };
  const auto at_two = headless("2", "two.json");
  const auto at_zero = headless("0", "zero.json");
  int differ_from_zero = 0;
  for (const char* key : {"error_bound_avg_pct", "error_bound_max_pct", "std_error_avg_pct"}) {
    ASSERT_TRUE(after[key].is_number()) << key << " " << after.dump();
    const double want = at_two[key].get<double>();
    // The window sums float pixels where `render` sums doubles.
    EXPECT_NEAR(after[key].get<double>(), want, 1e-4 * std::max(1.0, want)) << key;
    if (std::abs(at_zero[key].get<double>() - want) > 1e-3 * std::max(1.0, want))
      ++differ_from_zero;
  }
  EXPECT_EQ(differ_from_zero, 3);  // the check can fail: each figure moves with the exposure
}

}  // namespace
