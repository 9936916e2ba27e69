// `levrt render --rt-fallback` (renderer/rt_fallback.h): on by default, the stats record the
// probe's choice and its two costs; off, or for rt and the samplers, no probe is made (null); a
// value other than on/off exits 2 with one line naming the flag.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;

std::vector<std::string> fallback_render_args(const std::string& method, const fs::path& stats,
                                              std::vector<std::string> more) {
  std::vector<std::string> args = {"render",   "--scene", "building", "--level",     "3",
                                   "--width",  "32",      "--height", "24",          "--quiet",
                                   "--method", method,    "--stats",  stats.string()};
  // rt has no tolerance: the flag is refused with it.
  if (method != "rt") args.insert(args.end(), {"--tolerance", "0"});
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

nlohmann::json fallback_stats(const fs::path& stats) {
  return nlohmann::json::parse(levrt_test::read_file(stats));
}

TEST(RtFallbackCli, OnByDefaultTheStatsSayWhatTheProbeChose) {
  const levrt_test::TempDir dir("levrt_fallback_");
  const fs::path stats = dir.path() / "s.json";
  // lev at tolerance 0 casts all of rt's rays and walks besides: rt's loop is chosen.
  const CommandRun on = run_levrt(fallback_render_args("lev", stats, {}));
  ASSERT_EQ(on.exit_code, 0) << on.output;
  const nlohmann::json probe = fallback_stats(stats).at("rt_fallback");
  ASSERT_TRUE(probe.is_object());
  EXPECT_TRUE(probe.at("used").get<bool>());
  EXPECT_GT(probe.at("probe_points").get<int>(), 0);
  EXPECT_GT(probe.at("method_cost_rays").get<double>(), probe.at("rt_cost_rays").get<double>());
  EXPECT_EQ(fallback_stats(stats).at("nodes_visited_avg").get<double>(), 0.0);

  const CommandRun off = run_levrt(fallback_render_args("lev", stats, {"--rt-fallback", "off"}));
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_TRUE(fallback_stats(stats).at("rt_fallback").is_null());
  EXPECT_GT(fallback_stats(stats).at("nodes_visited_avg").get<double>(), 0.0);

  for (const char* method : {"rt", "lev_mc"}) {
    const CommandRun none = run_levrt(fallback_render_args(method, stats, {}));
    ASSERT_EQ(none.exit_code, 0) << none.output;
    EXPECT_TRUE(fallback_stats(stats).at("rt_fallback").is_null()) << method;
  }
}

TEST(RtFallbackCli, AValueOtherThanOnOrOffIsRefusedInOneLine) {
  const levrt_test::TempDir dir("levrt_fallback_");
  const fs::path stats = dir.path() / "s.json";
  const CommandRun r = run_levrt(fallback_render_args("lev", stats, {"--rt-fallback", "maybe"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--rt-fallback"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("maybe"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
  EXPECT_FALSE(fs::exists(stats));
}

}  // namespace
