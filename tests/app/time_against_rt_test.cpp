// The bench's time check against rt (app/bench/time_against_rt.h): a deterministic render over
// 1.1x rt's time is listed, with the share of rt's lights it tests and the reason that share
// gives; a render at or under the bound, or one not measured, is not.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/bench/time_against_rt.h"

namespace {

using app::bench::check_time_against_rt;

TEST(TimeAgainstRt, ARenderAtOrUnderTheBoundIsNotListed) {
  EXPECT_FALSE(check_time_against_rt("hall 4,096", "lev", 0.01, 1.1, 1.0, 10.0, 4096.0));
  EXPECT_FALSE(check_time_against_rt("hall 4,096", "lev", 0.01, 0.2, 1.0, 10.0, 4096.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(check_time_against_rt("hall 4,096", "lev", 0.01, nan, 1.0, 10.0, 4096.0));
  EXPECT_FALSE(check_time_against_rt("hall 4,096", "lev", 0.01, 2.0, nan, 10.0, 4096.0));
}

TEST(TimeAgainstRt, ASlowRenderIsListedWithTheReasonItsLightsGive) {
  const auto admits_most =
      check_time_against_rt("stage 4,608", "lev_bounded", 0.001, 1.32, 1.0, 4470.0, 4608.0);
  ASSERT_TRUE(admits_most);
  EXPECT_DOUBLE_EQ(admits_most->time_over_rt, 1.32);
  EXPECT_NEAR(admits_most->lights_tested_share, 0.97, 0.001);
  const std::string text = app::bench::slower_text(*admits_most);
  EXPECT_EQ(text.rfind("stage 4,608 lev_bounded 0.001: 1.32x rt's time; it tests 97 %", 0), 0u)
      << text;
  EXPECT_NE(text.find("admits most lights"), std::string::npos) << text;

  const auto costly_walk =
      check_time_against_rt("stage 4,608", "lev_cut", 0.005, 2.5, 1.0, 627.0, 4608.0);
  ASSERT_TRUE(costly_walk);
  const std::string walk = app::bench::slower_text(*costly_walk);
  EXPECT_NE(walk.find("tests 14 %"), std::string::npos) << walk;
  EXPECT_NE(walk.find("cost more than the shadow rays it saves"), std::string::npos) << walk;

  const auto all_overhead =
      check_time_against_rt("street_bare 64", "lightcuts", 0.02, 2.29, 1.0, 9.6, 6.0);
  ASSERT_TRUE(all_overhead);
  const std::string cut = app::bench::slower_text(*all_overhead);
  EXPECT_NE(cut.find("tests 160 %"), std::string::npos) << cut;
  EXPECT_NE(cut.find("all overhead"), std::string::npos) << cut;
}

}  // namespace
