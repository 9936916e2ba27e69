// `levrt render --heatmap-range LO,HI`: every heatmap is drawn over the given range (the viewer's
// scale from LO), so renders at two tolerances compare on one scale: the stats report that range
// for each, and the same value gets the same colour in both; a bad range exits 2 with one line
// naming the flag and writes nothing.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/render_command.h"
#include "app/settings.h"
#include "renderer/heatmap.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

std::vector<std::string> heatmap_render_args(std::vector<std::string> more) {
  std::vector<std::string> args = {"render", "--scene",  "maze", "--level", "1",        "--width",
                                   "24",     "--height", "18",   "--quiet", "--method", "lev"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(HeatmapRangeCli, EveryHeatmapOfEveryRenderIsDrawnOverTheGivenRange) {
  const levrt_test::TempDir dir("levrt_range_");
  for (const std::string tolerance : {"0.01", "0.3"}) {
    const fs::path stats = dir.path() / ("s" + tolerance + ".json");
    const CommandRun r = run_levrt(heatmap_render_args(
        {"--tolerance", tolerance, "--heatmap-range", "2,40", "--heatmap-lights",
         (dir.path() / ("l" + tolerance + ".png")).string(), "--stats", stats.string()}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(levrt_test::read_file(stats));
    for (const char* key : {"heatmap_lights_range", "heatmap_nodes_range", "heatmap_bound_range"}) {
      EXPECT_EQ(j[key][0].get<double>(), 2.0) << key;
      EXPECT_EQ(j[key][1].get<double>(), 40.0) << key;
    }
  }
  // The scale: the minimum and below at the bottom, the maximum and above at the top, log in
  // between from the minimum.
  renderer::HeatmapRange range{2.0, 40.0};
  const std::vector<std::uint8_t> rgb = renderer::heatmap_rgb8({1.0, 2.0, 40.0, 99.0}, range, true);
  EXPECT_EQ(range.min, 2.0);
  EXPECT_EQ(range.max, 40.0);
  EXPECT_EQ(glm::u8vec3(rgb[0], rgb[1], rgb[2]), renderer::viridis(0.0f));
  EXPECT_EQ(glm::u8vec3(rgb[3], rgb[4], rgb[5]), renderer::viridis(0.0f));
  EXPECT_EQ(glm::u8vec3(rgb[6], rgb[7], rgb[8]), renderer::viridis(1.0f));
  EXPECT_EQ(glm::u8vec3(rgb[9], rgb[10], rgb[11]), renderer::viridis(1.0f));
  EXPECT_DOUBLE_EQ(renderer::heatmap_position(renderer::heatmap_value_at(0.5, range), range), 0.5);
}

TEST(HeatmapRangeCli, ABadRangeExitsTwoWithOneLineAndWritesNothing) {
  const levrt_test::TempDir dir("levrt_range_bad_");
  const fs::path png = dir.path() / "l.png";
  for (const std::string bad : {"1", "5,2", "3,3", "-1,2", "a,b", "nan,4", "1,inf", "1,2,3", ""}) {
    const CommandRun r =
        run_levrt(heatmap_render_args({"--heatmap-range", bad, "--heatmap-lights", png.string()}));
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--heatmap-range"), std::string::npos) << bad << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << bad << ": " << r.output;
    EXPECT_FALSE(fs::exists(png)) << bad;
  }
}

// A range with no heatmap and no stats to draw it into was taken and changed nothing (exit 0):
// refused as a flag the method ignores is, one line naming it, exit 2, nothing written.
TEST(HeatmapRangeCli, ARangeWithNoHeatmapOrStatsIsRefused) {
  const levrt_test::TempDir dir("levrt_range_unused_");
  const fs::path image = dir.path() / "image.png";
  const CommandRun r =
      run_levrt(heatmap_render_args({"--heatmap-range", "0,5", "--out", image.string()}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.output.rfind("levrt: --heatmap-range: ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find("got '0,5'"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(image));
  const fs::path stats = dir.path() / "s.json";
  const CommandRun with_stats =
      run_levrt(heatmap_render_args({"--heatmap-range", "0,5", "--stats", stats.string()}));
  EXPECT_EQ(with_stats.exit_code, 0) << with_stats.output;
}

TEST(HeatmapRangeCli, ASubnormalEndIsTakenAsTypedLikeEverySetting) {
  const renderer::HeatmapRange tiny = app::parse_heatmap_range("1e-320,1");
  EXPECT_GT(tiny.min, 0.0);
  EXPECT_LT(tiny.min, 1e-300);
  EXPECT_DOUBLE_EQ(tiny.max, 1.0);
  EXPECT_DOUBLE_EQ(app::parse_heatmap_range("5e-324,1e-300").min, 5e-324);
  EXPECT_THROW(app::parse_heatmap_range("0,1e400"), app::UsageError);
}

}  // namespace
