// The split the light trees share (light_split.h): it parts every set into two non-empty parts
// holding each item once, in the input order, the same way every time; it parts spots by where
// they shine as well as by where they stand; and below its depth limit it splits at the median.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_split.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

std::vector<lev::SplitItem> items_of(const std::vector<lev::Light>& lights) {
  std::vector<lev::SplitItem> items;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const lev::Light& l = lights[i];
    items.push_back(lev::split_item({l.position, l.position}, lev::light_aggregate(l),
                                    static_cast<std::uint32_t>(i)));
  }
  return items;
}

// Random lights, some sets degenerate: every light at one place, or every light the same.
std::vector<lev::Light> random_set(Random& r, int set) {
  std::vector<lev::Light> lights;
  const int count = r.integer(2, 300);
  const lev::Light first = lev_test::random_light(r);
  for (int i = 0; i < count; ++i) {
    lev::Light light = set % 4 == 1 ? first : lev_test::random_light(r);
    if (set % 4 == 0) light.position = first.position;
    lights.push_back(light);
  }
  return lights;
}

std::vector<std::uint32_t> ids(const std::vector<lev::SplitItem>& items, std::size_t begin,
                               std::size_t end) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = begin; i < end; ++i) out.push_back(items[i].id);
  return out;
}

TEST(LightSplit, PartsEverySetIntoTwoNonEmptyPartsInInputOrderTheSameWayEveryTime) {
  Random r(31);
  for (int set = 0; set < 200; ++set) {
    const std::vector<lev::Light> lights = random_set(r, set);
    const std::vector<lev::SplitItem> input = items_of(lights);
    // A range inside the list, as a builder passes one: the items outside stay put.
    const std::size_t begin = static_cast<std::size_t>(r.integer(0, 1)) * input.size() / 4;
    const std::size_t end = input.size() - static_cast<std::size_t>(r.integer(0, 1));
    if (end - begin < 2) continue;
    const int depth = r.integer(0, lev::kMaxHeuristicSplitDepth + 2);
    const lev::SplitAt at = set % 2 == 0 ? lev::SplitAt::cheapest_boundary : lev::SplitAt::median;
    std::vector<lev::SplitItem> items = input;
    const std::size_t split = lev::split_items(items, begin, end, depth, at);
    ASSERT_GT(split, begin) << "set " << set;
    ASSERT_LT(split, end) << "set " << set;
    EXPECT_EQ(ids(items, 0, begin), ids(input, 0, begin));
    EXPECT_EQ(ids(items, end, items.size()), ids(input, end, input.size()));
    // Each part in the input order, and both together every item of the range once.
    const std::vector<std::uint32_t> left = ids(items, begin, split);
    const std::vector<std::uint32_t> right = ids(items, split, end);
    EXPECT_TRUE(std::is_sorted(left.begin(), left.end())) << "set " << set;
    EXPECT_TRUE(std::is_sorted(right.begin(), right.end())) << "set " << set;
    std::vector<std::uint32_t> both = left;
    both.insert(both.end(), right.begin(), right.end());
    std::sort(both.begin(), both.end());
    EXPECT_EQ(both, ids(input, begin, end)) << "set " << set;
    std::vector<lev::SplitItem> again = input;
    EXPECT_EQ(lev::split_items(again, begin, end, depth, at), split);
    EXPECT_EQ(ids(again, 0, again.size()), ids(items, 0, items.size()));
  }
}

// Two spots at each place of a grid (or side by side), one aimed up and one down, listed in turn.
TEST(LightSplit, SpotsAtOnePlaceAimedOppositeWaysPart) {
  for (const bool same_place : {true, false}) {
    const std::vector<lev::Light> lights =
        lev_test::opposite_spot_grid(same_place ? glm::vec3(0.0f) : glm::vec3(0.5f, 0.0f, 0.0f));
    for (const lev::SplitAt at : {lev::SplitAt::cheapest_boundary, lev::SplitAt::median}) {
      std::vector<lev::SplitItem> items = items_of(lights);
      const std::size_t split = lev::split_items(items, 0, items.size(), 0, at);
      ASSERT_EQ(split, 64u) << "same place " << same_place;
      for (std::size_t i = 0; i < items.size(); ++i) {
        EXPECT_EQ(items[i].axis, items[i < split ? 0 : split].axis) << "item " << i;
      }
      EXPECT_NE(items[0].axis, items[split].axis);
    }
  }
}

// Point lights shine everywhere: two groups far apart part by position.
TEST(LightSplit, PointLightsPartByPosition) {
  std::vector<lev::Light> lights;
  for (int k = 0; k < 40; ++k) {
    const float x =
        k % 2 == 0 ? 0.1f * static_cast<float>(k) : 100.0f + 0.1f * static_cast<float>(k);
    lights.push_back(lev::make_point_light({x, 0.0f, 0.0f}, glm::vec3(1.0f)));
  }
  std::vector<lev::SplitItem> items = items_of(lights);
  const std::size_t split = lev::split_items(items, 0, items.size(), 0, lev::SplitAt::median);
  ASSERT_EQ(split, 20u);
  for (std::size_t i = 0; i < items.size(); ++i)
    EXPECT_EQ(items[i].id % 2, i < split ? 0u : 1u) << "item " << i;
}

// At the depth limit the split is the median, however uneven the heuristic would make it: one
// bright light far from a row of dim ones would otherwise be split off alone.
TEST(LightSplit, AtTheDepthLimitSplitsAtTheMedian) {
  std::vector<lev::Light> lights;
  for (int k = 0; k < 100; ++k)
    lights.push_back(lev::make_point_light({static_cast<float>(k), 0, 0}, glm::vec3(0.01f)));
  lights.push_back(lev::make_point_light({1000.0f, 0, 0}, glm::vec3(1000.0f)));
  std::vector<lev::SplitItem> heuristic = items_of(lights);
  const lev::SplitAt at = lev::SplitAt::cheapest_boundary;
  EXPECT_EQ(lev::split_items(heuristic, 0, heuristic.size(), 0, at), 100u);
  std::vector<lev::SplitItem> median = items_of(lights);
  EXPECT_EQ(lev::split_items(median, 0, median.size(), lev::kMaxHeuristicSplitDepth, at), 50u);
}

TEST(LightSplit, OrientationMeasure) {
  // A single axis: the cone's measure, pi sin^2 of its half-angle.
  for (const double cone : {0.1, 0.5, 1.2}) {
    EXPECT_NEAR(lev::orientation_measure(0.0, cone), M_PI * std::sin(cone) * std::sin(cone), 1e-12);
  }
  // Shining everywhere: the whole sphere.
  EXPECT_NEAR(lev::orientation_measure(M_PI, 0.5 * M_PI), 4.0 * M_PI, 1e-12);
  // Wider spreads and wider cones measure more.
  double previous = 0.0;
  for (double spread = 0.0; spread <= M_PI; spread += 0.25) {
    const double m = lev::orientation_measure(spread, 0.3);
    EXPECT_GT(m, previous) << "spread " << spread;
    // (Until the spread and the cone together reach all the way round.)
    if (spread + 0.6 < M_PI) {
      EXPECT_GT(lev::orientation_measure(spread, 0.6), m) << "spread " << spread;
    }
    previous = m;
  }
}

}  // namespace
