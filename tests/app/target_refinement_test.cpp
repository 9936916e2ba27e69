// The targets experiment's search between grid settings (app/bench/target_refinement.h): the
// setting between two is their geometric mean to two significant digits; a method is searched
// only between its fastest render that meets the target and a looser one that misses it and was
// faster than every render that meets it, and never at a setting already rendered.
#include <gtest/gtest.h>

#include <vector>

#include "app/bench/target_refinement.h"
#include "lev/methods.h"

namespace {

using app::bench::setting_between;
using app::bench::SettingResult;
using app::bench::settings_to_try;

const lev::MethodInfo& method_named(const char* name) {
  return lev::method_info(*lev::parse_method(name));
}

TEST(TargetRefinement, TheSettingBetweenIsTheGeometricMeanToTwoDigits) {
  EXPECT_DOUBLE_EQ(setting_between(0.01, 0.003), 0.0055);    // 0.005477
  EXPECT_DOUBLE_EQ(setting_between(0.0055, 0.003), 0.0041);  // 0.004062
  EXPECT_DOUBLE_EQ(setting_between(0.01, 0.0055), 0.0074);   // 0.007416
  EXPECT_DOUBLE_EQ(setting_between(0.1, 0.001), 0.01);
  EXPECT_DOUBLE_EQ(setting_between(0.02, 0.01), 0.014);  // 0.014142
  EXPECT_EQ(setting_between(0.01, 0.0), 0.0);
  EXPECT_EQ(setting_between(-1.0, 0.01), 0.0);
}

TEST(TargetRefinement, SearchesBetweenTheFastestThatMeetsAndAFasterLooserOne) {
  const lev::MethodInfo* lev = &method_named("lev");
  // lev meets the target at 0.003 (248x) and misses it at 0.01 (530x): 0.0055 is worth a render.
  const std::vector<SettingResult> renders{{lev, 0.1, 900.0, false},
                                           {lev, 0.01, 530.0, false},
                                           {lev, 0.003, 248.0, true},
                                           {lev, 0.001, 120.0, true}};
  const auto next = settings_to_try(renders);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].method, lev);
  EXPECT_DOUBLE_EQ(next[0].setting, 0.0055);
}

TEST(TargetRefinement, ALooserSettingNoFasterThanTheBestIsNotSearched) {
  const lev::MethodInfo* lev = &method_named("lev");
  const lev::MethodInfo* cut = &method_named("lev_cut");
  // lev_cut misses at 0.01 with 40x while lev meets the target at 248x: nothing lev_cut could
  // reach between 0.01 and 0.005 beats lev.
  const std::vector<SettingResult> renders{{lev, 0.01, 530.0, false},
                                           {lev, 0.003, 248.0, true},
                                           {cut, 0.01, 40.0, false},
                                           {cut, 0.005, 20.0, true}};
  const auto next = settings_to_try(renders);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].method, lev);
}

TEST(TargetRefinement, NothingToSearchWithoutAMissingLooserNeighbour) {
  const lev::MethodInfo* lev = &method_named("lev");
  const lev::MethodInfo* tree = &method_named("light_tree");
  // The loosest setting meets the target; no setting meets it; a method swept over no setting.
  EXPECT_TRUE(settings_to_try({{lev, 0.1, 900.0, true}, {lev, 0.01, 500.0, true}}).empty());
  EXPECT_TRUE(settings_to_try({{lev, 0.1, 900.0, false}, {lev, 0.01, 500.0, false}}).empty());
  EXPECT_TRUE(settings_to_try({{tree, 0.01, 900.0, true}}).empty());
}

TEST(TargetRefinement, ASettingAlreadyRenderedIsNotAskedAgainAndTheSearchNarrows) {
  const lev::MethodInfo* lev = &method_named("lev");
  // Round 1 rendered 0.0055, which missed: round 2 searches between 0.0055 and 0.003.
  std::vector<SettingResult> renders{
      {lev, 0.01, 530.0, false}, {lev, 0.0055, 400.0, false}, {lev, 0.003, 248.0, true}};
  auto next = settings_to_try(renders);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_DOUBLE_EQ(next[0].setting, 0.0041);
  // Round 2 rendered 0.0041, which met the target: the gap to 0.0055 is searched next.
  renders.push_back({lev, 0.0041, 330.0, true});
  next = settings_to_try(renders);
  ASSERT_EQ(next.size(), 1u);
  EXPECT_DOUBLE_EQ(next[0].setting, 0.0047);  // 0.004749
  // Once the settings are too close for two digits to part them, the search stops.
  const std::vector<SettingResult> close{{lev, 0.0042, 340.0, false}, {lev, 0.0041, 330.0, true}};
  EXPECT_TRUE(settings_to_try(close).empty());
}

}  // namespace
