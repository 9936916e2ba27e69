// The CI uses of `levrt render`: --fail-above gates on the pixel error against
// the rt reference (exit 3 with one line above, 0 at or below, 2 for a bad value or without
// --reference), --heatmap-error draws that error per pixel, --reference-out writes rt's image.
#include "app/accuracy_gate.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {

using levrt_test::line_count;
using levrt_test::read_file;
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

// A small lev render with visible culling error (a coarse tolerance).
std::vector<std::string> gate_render_args(std::vector<std::string> more) {
  std::vector<std::string> args = {"render", "--width",     "24",  "--height",
                                   "18",     "--tolerance", "0.3", "--quiet"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The same render with rt, which has no tolerance (the flag is refused with it).
std::vector<std::string> gate_rt_render_args(std::vector<std::string> more) {
  std::vector<std::string> args = {"render", "--width", "24",       "--height",
                                   "18",     "--quiet", "--method", "rt"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(AccuracyGate, ParsesEitherLimitOrBoth) {
  const app::AccuracyGate both = app::parse_accuracy_gate("avg=0.5,max=12");
  EXPECT_DOUBLE_EQ(*both.avg_pct, 0.5);
  EXPECT_DOUBLE_EQ(*both.max_pct, 12.0);
  const app::AccuracyGate max_first = app::parse_accuracy_gate("max=3,avg=0");
  EXPECT_DOUBLE_EQ(*max_first.avg_pct, 0.0);
  EXPECT_DOUBLE_EQ(*max_first.max_pct, 3.0);
  EXPECT_FALSE(app::parse_accuracy_gate("avg=1").max_pct.has_value());
  EXPECT_FALSE(app::parse_accuracy_gate("max=1").avg_pct.has_value());
}

TEST(AccuracyGate, RefusesBadValuesNamingTheFlagAndTheText) {
  for (const std::string bad :
       {"", "avg=-1", "avg=nan", "max=NaN", "max=inf", "avg=", "avg=1x", "avg=1,avg=2", "mean=1",
        "avg", "avg=1,", ",max=1", "avg=1;max=2"}) {
    try {
      app::parse_accuracy_gate(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const app::UsageError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("--fail-above: ", 0), 0u) << message;
      EXPECT_NE(message.find("got '" + bad + "'"), std::string::npos) << message;
    }
  }
}

TEST(AccuracyGate, FailsOnlyAboveALimit) {
  const app::AccuracyGate gate = app::parse_accuracy_gate("avg=1,max=10");
  EXPECT_FALSE(app::accuracy_gate_failure(gate, {1.0, 10.0}));
  EXPECT_FALSE(app::accuracy_gate_failure(gate, {0.0, 0.0}));
  const auto avg = app::accuracy_gate_failure(gate, {1.01, 5.0});
  ASSERT_TRUE(avg);
  EXPECT_NE(avg->find("avg"), std::string::npos);
  EXPECT_EQ(avg->find("max"), std::string::npos);
  const auto max = app::accuracy_gate_failure(gate, {0.5, 10.5});
  ASSERT_TRUE(max);
  EXPECT_NE(max->find("max"), std::string::npos);
  EXPECT_FALSE(app::accuracy_gate_failure(app::parse_accuracy_gate("max=10"), {50.0, 1.0}));
}

TEST(AccuracyGate, TheMessageShowsTheLimitAsTypedAndTheErrorAboveIt) {
  const auto tiny =
      app::accuracy_gate_failure(app::parse_accuracy_gate("avg=0.00001"), {0.00002, 0.0});
  ASSERT_TRUE(tiny);
  EXPECT_EQ(*tiny, "--fail-above: pixel error avg 2e-05% above avg=0.00001%");
  const auto close = app::accuracy_gate_failure(app::parse_accuracy_gate("max=1"), {0.0, 1.00004});
  ASSERT_TRUE(close);
  EXPECT_EQ(*close, "--fail-above: pixel error max 1.00004% above max=1%");
  const auto usual =
      app::accuracy_gate_failure(app::parse_accuracy_gate("avg=0.5,max=2"), {7.13102, 23.0});
  ASSERT_TRUE(usual);
  EXPECT_EQ(*usual,
            "--fail-above: pixel error avg 7.1310% above avg=0.5%, pixel error max 23.0000% above "
            "max=2%");
}

TEST(AccuracyGateCli, ExitsThreeWithOneLineAboveAndZeroAtOrBelow) {
  const levrt_test::TempDir dir("levrt_gate_");
  const std::string stats = (dir.path() / "s.json").string();
  const CommandRun measured = run_levrt(gate_render_args({"--reference", "rt", "--stats", stats}));
  ASSERT_EQ(measured.exit_code, 0) << measured.output;
  const nlohmann::json json = nlohmann::json::parse(read_file(stats));
  const double avg = json["pixel_error_avg_pct"].get<double>();
  const double max = json["pixel_error_max_pct"].get<double>();
  ASSERT_GT(avg, 0.0) << "the render must have an error for the gate to see";

  const auto gate = [&](double a, double m) {
    std::ostringstream text;
    text.precision(17);
    text << "avg=" << a << ",max=" << m;
    return run_levrt(gate_render_args({"--reference", "rt", "--fail-above", text.str()}));
  };
  const CommandRun at = gate(avg, max);
  EXPECT_EQ(at.exit_code, 0) << at.output;
  EXPECT_EQ(at.output, "");
  const CommandRun above_avg = gate(avg * 0.5, max * 2.0);
  EXPECT_EQ(above_avg.exit_code, app::kAccuracyGateExitCode) << above_avg.output;
  EXPECT_EQ(line_count(above_avg.output), 1) << above_avg.output;
  EXPECT_NE(above_avg.output.find("--fail-above: pixel error avg"), std::string::npos)
      << above_avg.output;
  const CommandRun above_max = gate(avg * 2.0, max * 0.5);
  EXPECT_EQ(above_max.exit_code, app::kAccuracyGateExitCode) << above_max.output;
  EXPECT_EQ(line_count(above_max.output), 1) << above_max.output;
  EXPECT_NE(above_max.output.find("pixel error max"), std::string::npos) << above_max.output;
}

TEST(AccuracyGateCli, AFailedGateStillWritesEveryOutput) {
  const levrt_test::TempDir dir("levrt_gate_");
  const fs::path image = dir.path() / "img.png";
  const fs::path error = dir.path() / "error.png";
  const CommandRun r =
      run_levrt(gate_render_args({"--reference", "rt", "--fail-above", "avg=0", "--out",
                                  image.string(), "--heatmap-error", error.string()}));
  EXPECT_EQ(r.exit_code, app::kAccuracyGateExitCode) << r.output;
  EXPECT_TRUE(fs::is_regular_file(image));
  EXPECT_TRUE(fs::is_regular_file(error));
}

TEST(AccuracyGateCli, BadValuesAndAMissingReferenceExitTwoWithOneLine) {
  const levrt_test::TempDir dir("levrt_gate_");
  const std::string png = (dir.path() / "x.png").string();
  const std::vector<std::vector<std::string>> bad = {
      {"--reference", "rt", "--fail-above", "avg=-0.5"},
      {"--reference", "rt", "--fail-above", "max=nan"},
      {"--reference", "rt", "--fail-above", "avg=1,mean=2"},
      {"--fail-above", "avg=1,max=2"},
      {"--heatmap-error", png},
      {"--reference-out", png},
      {"--reference", "rt", "--heatmap-error", (dir.path() / "x.jpg").string()},
  };
  for (const std::vector<std::string>& flags : bad) {
    const CommandRun r = run_levrt(gate_render_args(flags));
    EXPECT_EQ(r.exit_code, 2) << flags[0] << " " << flags[1] << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(flags[0] == "--reference" ? flags[2] : flags[0]), std::string::npos)
        << r.output;
  }
  EXPECT_FALSE(fs::exists(png));
}

TEST(AccuracyGateCli, ReferenceOutIsRtsImageAndTheErrorHeatmapIsZeroAgainstItself) {
  const levrt_test::TempDir dir("levrt_gate_");
  const fs::path reference = dir.path() / "reference.png";
  const fs::path error = dir.path() / "error.png";
  const fs::path stats = dir.path() / "s.json";
  const fs::path rt_image = dir.path() / "rt.png";
  const CommandRun lev =
      run_levrt(gate_render_args({"--reference", "rt", "--reference-out", reference.string(),
                                  "--heatmap-error", error.string(), "--stats", stats.string()}));
  ASSERT_EQ(lev.exit_code, 0) << lev.output;
  const CommandRun rt = run_levrt(gate_rt_render_args({"--out", rt_image.string()}));
  ASSERT_EQ(rt.exit_code, 0) << rt.output;
  EXPECT_EQ(read_file(reference), read_file(rt_image));
  const nlohmann::json json = nlohmann::json::parse(read_file(stats));
  // The heatmap spans the per-pixel errors: its top is the maximum error.
  EXPECT_DOUBLE_EQ(json["heatmap_error_range"][1].get<double>(),
                   json["pixel_error_max_pct"].get<double>());

  // rt against itself: every pixel 0, one colour.
  const fs::path rt_error = dir.path() / "rt_error.png";
  const fs::path rt_stats = dir.path() / "rt.json";
  const CommandRun self =
      run_levrt(gate_rt_render_args({"--reference", "rt", "--heatmap-error", rt_error.string(),
                                     "--stats", rt_stats.string(), "--fail-above", "avg=0,max=0"}));
  EXPECT_EQ(self.exit_code, 0) << self.output;
  const nlohmann::json rt_json = nlohmann::json::parse(read_file(rt_stats));
  EXPECT_EQ(rt_json["heatmap_error_range"][1].get<double>(), 0.0);
  EXPECT_NE(read_file(rt_error), read_file(error));
}

}  // namespace
