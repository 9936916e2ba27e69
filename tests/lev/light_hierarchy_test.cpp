#include "lev/light_hierarchy.h"

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_bvh.h"
#include "lev/light_description.h"

namespace {

bool same_light_with_dropoff(const lev::Light& a, const lev::Light& b) {
  return a.position == b.position && a.intensity == b.intensity && a.direction == b.direction &&
         a.kind == b.kind && a.cos_cone_half_angle == b.cos_cone_half_angle &&
         a.dropoff == b.dropoff;
}

// A recursively instanced scene in the style of the thesis' building: master 0 holds a point
// light and a spotlight; master k puts four rotated, translated and scaled copies of k-1.
lev::LightDescription instanced_tree(int levels) {
  lev::LightDescription tree;
  tree.masters.push_back(lev::union_node(
      {lev::light_node(lev::make_point_light({1.0f, 2.0f, 3.0f}, {3.0f, 2.0f, 1.0f})),
       lev::affine_node(lev::make_translation({4.0f, 0.5f, 2.0f}),
                        lev::light_node(lev::make_spot_light({0, 0, 0}, {0.3f, 0.1f, -1.0f},
                                                             {6, 6, 6}, 0.7f, 3.0f)))}));
  for (int k = 1; k <= levels; ++k) {
    std::vector<lev::LightDescriptionNode> children;
    const float block = 10.0f * static_cast<float>(1 << (k - 1));
    for (int q = 0; q < 4; ++q) {
      lev::Similarity xf =
          lev::compose(lev::make_translation({block * (q % 2), block * (q / 2), 0.0f}),
                       lev::make_rotation({0, 0, 1}, 0.3f * q));
      if (q == 3) xf = lev::compose(xf, lev::make_scale(0.8f));
      children.push_back(
          lev::affine_node(xf, lev::instance_node(static_cast<std::uint32_t>(k - 1))));
    }
    tree.masters.push_back(lev::union_node(std::move(children)));
  }
  tree.root = lev::instance_node(static_cast<std::uint32_t>(levels));
  return tree;
}

std::vector<glm::vec3> hierarchy_probe_points() {
  std::vector<glm::vec3> points;
  for (int i = 0; i < 40; ++i) {
    points.push_back({1.7f * i - 3.0f, 0.9f * i + 1.0f, 0.25f * (i % 7)});
  }
  return points;
}

TEST(LightHierarchy, InstancedWalkMatchesFlattenedBruteForce) {
  const lev::LightDescription tree = instanced_tree(3);
  lev::LightHierarchy h = lev::build_hierarchy(tree);
  EXPECT_EQ(h.light_count, 2u * 64u);
  const std::vector<lev::Light> flat = lev::flatten_lights(h);
  ASSERT_EQ(flat.size(), h.light_count);
  lev::WalkScratch scratch;
  for (float tau : {0.0f, 0.001f, 0.01f, 0.1f, 1.0f}) {
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
    for (const glm::vec3& p : hierarchy_probe_points()) {
      std::vector<lev::Light> found;
      lev::WalkCounters counters;
      lev::find_important_lights(h, volumes, tau, p, scratch, found, counters);
      const std::vector<lev::Light> expected = lev::important_lights_brute_force(flat, p, tau);
      ASSERT_EQ(found.size(), expected.size()) << "tau " << tau;
      for (std::size_t i = 0; i < found.size(); ++i) {
        ASSERT_TRUE(same_light_with_dropoff(found[i], expected[i]))
            << "tau " << tau << " light " << i;
      }
      if (tau > 0.0f) {
        EXPECT_GT(counters.nodes_visited, 0u);
      }
    }
  }
}

TEST(LightHierarchy, ToleranceZeroReturnsEveryLight) {
  lev::LightHierarchy h = lev::build_hierarchy(instanced_tree(2));
  const std::vector<lev::Light> flat = lev::flatten_lights(h);
  lev::WalkScratch scratch;
  std::vector<lev::Light> found;
  lev::WalkCounters counters;
  // Point lights light every point; spots only inside their cones. At tolerance 0 the walk must
  // return every light with non-zero irradiance, so all the point lights at least.
  lev::find_important_lights(h, lev::fit_extent_volumes(h, 0.0f), 0.0f, {5.0f, 5.0f, 1.0f}, scratch,
                             found, counters);
  std::size_t point_lights = 0;
  for (const lev::Light& l : flat) point_lights += l.kind == lev::LightKind::point;
  std::size_t found_points = 0;
  for (const lev::Light& l : found) found_points += l.kind == lev::LightKind::point;
  EXPECT_EQ(found_points, point_lights);
  EXPECT_EQ(found.size(), lev::important_lights_brute_force(flat, {5.0f, 5.0f, 1.0f}, 0.0f).size());
}

TEST(LightHierarchy, ScaledInstanceShinesWithScaleSquared) {
  lev::LightDescription tree;
  tree.masters.push_back(lev::light_node(lev::make_point_light({1, 0, 0}, {2, 2, 2})));
  tree.root = lev::affine_node(
      lev::compose(lev::make_translation({5, 0, 0}), lev::make_scale(3.0f)), lev::instance_node(0));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> flat = lev::flatten_lights(h);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_EQ(flat[0].position, glm::vec3(8, 0, 0));
  EXPECT_EQ(flat[0].intensity, glm::vec3(18, 18, 18));
}

TEST(LightHierarchy, RefitKeepsStructureAndComputesMastersOnce) {
  const lev::LightHierarchy h = lev::build_hierarchy(instanced_tree(4));
  const std::size_t nodes = h.nodes.size(), bytes = lev::hierarchy_bytes(h);
  const lev::Bounds before =
      lev::fit_extent_volumes(h, 0.01f).nodes[h.master_ranges[0].begin].volume;
  const lev::ExtentVolumes refit = lev::fit_extent_volumes(h, 0.001f);
  EXPECT_EQ(refit.nodes.size(), nodes);
  EXPECT_EQ(lev::hierarchy_bytes(h), bytes);
  const lev::Bounds after = refit.nodes[h.master_ranges[0].begin].volume;
  EXPECT_LT(after.lo.x, before.lo.x);  // larger tolerance volume for a smaller tolerance
  // One master per level: the node count is independent of the 4^levels instances.
  const lev::LightHierarchy bigger = lev::build_hierarchy(instanced_tree(8));
  EXPECT_EQ(bigger.light_count, 2u * 65536u);
  EXPECT_LT(bigger.nodes.size(), 100u);
}

TEST(LightHierarchy, RejectsMalformedTrees) {
  lev::LightDescription forward;
  forward.masters.push_back(lev::instance_node(0));  // instances itself
  EXPECT_THROW(lev::build_hierarchy(forward), std::invalid_argument);
  lev::LightDescription bad_scale;
  lev::Similarity xf;
  xf.scale = 0.0f;
  bad_scale.root =
      lev::affine_node(xf, lev::light_node(lev::make_point_light({0, 0, 0}, {1, 1, 1})));
  EXPECT_THROW(lev::build_hierarchy(bad_scale), std::invalid_argument);
  lev::LightDescription deep;
  lev::LightDescriptionNode n = lev::light_node(lev::make_point_light({0, 0, 0}, {1, 1, 1}));
  for (int i = 0; i < lev::kMaxTreeDepth + 5; ++i) n = lev::extent_volume_node(std::move(n));
  deep.root = std::move(n);
  EXPECT_THROW(lev::build_hierarchy(deep), std::invalid_argument);
}

TEST(LightBvh, FlatListGetsAHierarchyThatCullsExactly) {
  std::vector<lev::Light> lights;
  std::uint64_t seed = 7;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(seed >> 40) / static_cast<float>(1ull << 24);
  };
  for (int i = 0; i < 3000; ++i) {
    const glm::vec3 p(200.0f * uniform(), 200.0f * uniform(), 5.0f * uniform());
    if (i % 3 == 0) {
      lights.push_back(lev::make_spot_light(p, {uniform() - 0.5f, uniform() - 0.5f, -1.0f},
                                            glm::vec3(0.5f + 2.0f * uniform()), 0.2f + uniform(),
                                            4.0f * uniform()));
    } else {
      lights.push_back(lev::make_point_light(p, glm::vec3(0.5f + 2.0f * uniform(), 1.0f, 0.5f)));
    }
  }
  lev::LightDescription tree;
  tree.root = lev::build_light_bvh(lights);
  lev::LightHierarchy h = lev::build_hierarchy(tree);
  EXPECT_EQ(h.light_count, lights.size());
  const std::vector<lev::Light> flat = lev::flatten_lights(h);
  lev::WalkScratch scratch;
  for (float tau : {0.001f, 0.01f, 0.1f}) {
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
    std::uint64_t visited = 0;
    for (int k = 0; k < 200; ++k) {
      const glm::vec3 p(200.0f * uniform(), 200.0f * uniform(), 3.0f * uniform());
      std::vector<lev::Light> found;
      lev::WalkCounters counters;
      lev::find_important_lights(h, volumes, tau, p, scratch, found, counters);
      const auto expected = lev::important_lights_brute_force(flat, p, tau);
      ASSERT_EQ(found.size(), expected.size());
      for (std::size_t i = 0; i < found.size(); ++i)
        ASSERT_TRUE(same_light_with_dropoff(found[i], expected[i]));
      visited += counters.nodes_visited;
    }
    // The hierarchy culls: far fewer volumes tested than lights.
    EXPECT_LT(visited / 200, lights.size() / 4) << "tau " << tau;
  }
}

}  // namespace
