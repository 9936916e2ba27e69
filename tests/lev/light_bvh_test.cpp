// The automatic hierarchy (light_bvh.h) over random lights, degenerate sets among them: it holds
// every light exactly once, it is the same hierarchy every time it is built, and it parts spots
// aimed different ways before anything else.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "lev/important_lights.h"
#include "lev/light_bvh.h"
#include "lev/light_description.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

// The lights of a subtree, in its order.
std::vector<lev::Light> lights_below(const lev::LightDescriptionNode& node) {
  lev::LightDescription tree;
  tree.root = node;
  return lev::flatten_light_description(tree);
}

TEST(LightBvh, HoldsEveryLightOnceAndIsTheSameEveryTime) {
  Random r(41);
  for (int set = 0; set < 60; ++set) {
    const int count = r.integer(1, 500);
    std::vector<lev::Light> lights;
    const lev::Light first = lev_test::random_light(r);
    for (int i = 0; i < count; ++i) {
      lev::Light light = lev_test::random_light(r);
      if (set % 3 == 0) light.position = first.position;  // every light at one place
      // Light i is known by its red intensity, i + 1.
      light.intensity = glm::vec3(static_cast<float>(i + 1), 1.0f, 1.0f);
      lights.push_back(light);
    }
    const lev::LightDescriptionNode root = lev::build_light_bvh(lights);
    const std::vector<lev::Light> flat = lights_below(root);
    ASSERT_EQ(flat.size(), lights.size()) << "set " << set;
    std::vector<int> seen(lights.size(), 0);
    for (const lev::Light& l : flat) ++seen.at(static_cast<std::size_t>(l.intensity.x) - 1);
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "light " << i;
    lev_test::expect_same_lights(lights_below(lev::build_light_bvh(lights)), flat,
                                 "set " + std::to_string(set));
  }
}

// At every place of a grid a spot aimed up and one aimed down: the root's first split parts
// them by their aim (a split by position alone would leave both ways in every child), so each
// of the root's children holds spots aimed one way only.
TEST(LightBvh, PartsSpotsAimedOppositeWaysFirst) {
  const std::vector<lev::Light> lights = lev_test::opposite_spot_grid();
  const lev::LightDescriptionNode root = lev::build_light_bvh(lights);
  ASSERT_EQ(root.kind, lev::NodeKind::extent_volume);
  const lev::LightDescriptionNode& children = root.children.at(0);
  ASSERT_EQ(children.children.size(), 4u);
  int up = 0;
  for (const lev::LightDescriptionNode& child : children.children) {
    const std::vector<lev::Light> below = lights_below(child);
    ASSERT_FALSE(below.empty());
    for (const lev::Light& l : below) EXPECT_EQ(l.direction, below[0].direction);
    if (below[0].direction.z > 0.0f) ++up;
  }
  EXPECT_EQ(up, 2);
}

}  // namespace
