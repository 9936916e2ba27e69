// The bench's monotonicity check (app/bench/monotonicity.h): it finds every tighter setting that
// erred more than a looser one, on the average or the maximum, names both settings and both
// errors in one line, and finds nothing in a sweep whose errors only shrink or hold.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/bench/monotonicity.h"

namespace {

using app::bench::find_monotonicity_violations;
using app::bench::SweepPoint;

SweepPoint point(double setting, double average_pct, double max_pct) {
  SweepPoint p;
  p.setting = setting;
  p.errors.average_pct = average_pct;
  p.errors.max_pct = max_pct;
  return p;
}

TEST(Monotonicity, ShrinkingOrEqualErrorsPass) {
  EXPECT_TRUE(find_monotonicity_violations("hall 1,024", "lev",
                                           {point(0.1, 1.0, 5.0), point(0.01, 1.0, 5.0),
                                            point(0.001, 0.2, 1.0), point(0.0, 0.0, 0.0)})
                  .empty());
  EXPECT_TRUE(find_monotonicity_violations("hall 1,024", "lev", {}).empty());
}

TEST(Monotonicity, EveryLooserSettingIsCompared) {
  // lev_est on hall 16,384 before its gate shrank with the tolerance (80x60).
  const auto violations = find_monotonicity_violations(
      "hall 16,384", "lev_est",
      {point(0.003, 0.5, 4.0), point(0.001, 0.0586, 1.046), point(0.0003, 0.1387, 3.922)});
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].looser.setting, 0.001);
  EXPECT_EQ(violations[0].tighter.setting, 0.0003);
  EXPECT_EQ(app::bench::violation_text(violations[0]),
            "hall 16,384 lev_est: 0.0003 after 0.001: avg 0.139 % > 0.0586 %, max 3.92 % > 1.05 %");
  // Only the maximum grew, against the first setting and not the second.
  const auto max_only = find_monotonicity_violations(
      "stage 4,608", "lev_cut",
      {point(0.1, 1.0, 2.0), point(0.05, 0.5, 3.0), point(0.02, 0.4, 2.5)});
  ASSERT_EQ(max_only.size(), 2u);
  EXPECT_EQ(app::bench::violation_text(max_only[0]),
            "stage 4,608 lev_cut: 0.05 after 0.1: max 3 % > 2 %");
  EXPECT_EQ(app::bench::violation_text(max_only[1]),
            "stage 4,608 lev_cut: 0.02 after 0.1: max 2.5 % > 2 %");
}

TEST(Monotonicity, UnmatchedRendersAreNotCompared) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(
      find_monotonicity_violations("maze 45", "ast", {point(1.0, nan, nan), point(0.1, 0.5, 2.0)})
          .empty());
}

}  // namespace
