// `levrt render --heatmap-missed` and `--missed-draws` (renderer/missed_light.h): the heatmap
// turns the estimate on and the stats carry its keys; without either the keys are absent; a
// count of 1 (no spread for a standard error) exits 2 with one line.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/json_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {

using levrt_test::read_json;
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

std::vector<std::string> missed_render_args(std::vector<std::string> more) {
  std::vector<std::string> args = {"render", "--scene",  "maze", "--level",     "1",    "--width",
                                   "24",     "--height", "18",   "--tolerance", "0.05", "--quiet"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(MissedLightCli, TheHeatmapTurnsTheEstimateOnWithSixteenDraws) {
  const levrt_test::TempDir dir("levrt_missed_");
  const fs::path png = dir.path() / "missed.png";
  const fs::path stats = dir.path() / "s.json";
  const CommandRun r =
      run_levrt(missed_render_args({"--heatmap-missed", png.string(), "--stats", stats.string()}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(png));
  const nlohmann::json j = read_json(stats);
  EXPECT_EQ(j["missed_draws"].get<int>(), 16);
  EXPECT_GT(j["missed_estimate_avg_pct"].get<double>(), 0.0);
  EXPECT_GE(j["missed_estimate_max_pct"].get<double>(), j["missed_estimate_avg_pct"].get<double>());
  EXPECT_GT(j["missed_estimate_std_error_avg_pct"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["heatmap_missed_range"][1].get<double>(),
                   j["missed_estimate_max_pct"].get<double>());
}

TEST(MissedLightCli, OffUnlessAskedAndACountOfOneIsRefused) {
  const levrt_test::TempDir dir("levrt_missed_");
  const fs::path stats = dir.path() / "s.json";
  const CommandRun off = run_levrt(missed_render_args({"--stats", stats.string()}));
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_FALSE(read_json(stats).contains("missed_estimate_avg_pct"));
  const CommandRun on =
      run_levrt(missed_render_args({"--missed-draws", "4", "--stats", stats.string()}));
  ASSERT_EQ(on.exit_code, 0) << on.output;
  EXPECT_EQ(read_json(stats)["missed_draws"].get<int>(), 4);
  const CommandRun one = run_levrt(missed_render_args({"--missed-draws", "1"}));
  EXPECT_EQ(one.exit_code, 2) << one.output;
  EXPECT_EQ(std::count(one.output.begin(), one.output.end(), '\n'), 1) << one.output;
  EXPECT_NE(one.output.find("--missed-draws"), std::string::npos) << one.output;
}

}  // namespace
