// `lev_est`'s walk (find_lights_and_clusters) on random instanced scenes: it returns the lights
// find_important_lights returns, its culled bound is at least the irradiance of every light not
// returned, and its clusters account for every culled light exactly once (their intensities sum
// to the culled lights'). The selector reports the walk's bound and, at tolerance 0, gives rt's
// radiance.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "lev/selector_lev_est.h"
#include "lev/selector_rt.h"
#include "tests/lev/open_point.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::OpenPoint;
using lev_test::Random;

// A random instanced tree, and for odd seeds one more master whose lights sit right below their
// transforms, without an extent volume of their own (a moved light is then culled by its box).
lev::LightDescription random_lev_est_tree(Random& r, std::uint64_t seed) {
  lev::LightDescription tree = lev_test::random_instanced_tree(r);
  if (seed % 2 == 0) return tree;
  std::vector<lev::LightDescriptionNode> lights;
  for (int k = 0; k < 6; ++k) {
    lights.push_back(lev::affine_node(lev_test::random_similarity(r),
                                      lev::light_node(lev_test::random_light(r))));
  }
  tree.masters.push_back(lev::union_node(std::move(lights)));
  const auto master = static_cast<std::uint32_t>(tree.masters.size() - 1);
  tree.root.children.push_back(
      lev::affine_node(lev_test::random_similarity(r), lev::instance_node(master)));
  return tree;
}

TEST(LevEst, ClustersAccountForEveryCulledLightAndTheBoundHolds) {
  std::uint64_t clustered_points = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = random_lev_est_tree(r, seed);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    lev::WalkScratch scratch;
    for (const float tau : {0.0f, 1e-3f, 1e-2f, 0.1f, 1.0f, 1e30f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      for (int k = 0; k < 40; ++k) {
        const glm::vec3 x(r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-15, 15));
        const std::string context = "seed " + std::to_string(seed) + " tau " + std::to_string(tau) +
                                    " k " + std::to_string(k);
        std::vector<lev::Light> plain, found, clusters;
        lev::WalkCounters counters;
        lev::find_important_lights(h, volumes, tau, x, scratch, plain, counters);
        // Every culled part kept, whatever its bound, cut at a random coarseness.
        lev::ClusterCut cut;
        cut.refine_above = std::pow(10.0f, r.uniform(-4.0f, 4.0f));
        cut.keep_above = -1.0f;
        glm::vec3 bound(-1.0f);
        lev::find_lights_and_clusters(h, volumes, tau, cut, x, scratch, found, clusters, counters,
                                      &bound);
        lev_test::expect_same_lights(found, plain, context);
        glm::dvec3 culled_irradiance(0.0), culled_intensity(0.0), cluster_intensity(0.0);
        for (const lev::Light& l : world_lights) {
          if (lev::is_important(l, x, tau)) continue;
          culled_irradiance += glm::dvec3(lev::irradiance(l, x));
          culled_intensity += glm::dvec3(l.intensity);
        }
        for (const lev::Light& c : clusters) cluster_intensity += glm::dvec3(c.intensity);
        for (int c = 0; c < 3; ++c) {
          ASSERT_GE(static_cast<double>(bound[c]), culled_irradiance[c])
              << context << ", channel " << c;
          ASSERT_NEAR(cluster_intensity[c], culled_intensity[c], 1e-4 * culled_intensity[c] + 1e-30)
              << context << ", channel " << c;
        }
        if (tau == 0.0f) {
          ASSERT_EQ(bound, glm::vec3(0.0f)) << context;
        }
        if (clusters.size() > 1 && clusters.size() < world_lights.size() - found.size())
          ++clustered_points;
      }
    }
  }
  // Subtrees were culled whole into clusters of several lights at many points.
  EXPECT_GT(clustered_points, 1000u);
}

TEST(LevEst, SelectorBoundHoldsAndToleranceZeroIsRt) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    const lev::RtSelector rt(h);
    for (const float tau : {0.0f, 1e-2f, 1.0f}) {
      const lev::LevEstSelector est(h, tau);
      for (int k = 0; k < 30; ++k) {
        const glm::vec3 x(r.uniform(-30, 30), r.uniform(-30, 30), r.uniform(-10, 10));
        OpenPoint point(x);
        lev::SelectorScratch scratch;
        lev::SelectionCounters counters;
        glm::vec3 bound(-1.0f);
        const glm::vec3 radiance = est.direct_radiance(point, scratch, counters, &bound);
        glm::dvec3 culled(0.0);
        for (const lev::Light& l : world_lights) {
          if (!lev::is_important(l, x, tau)) culled += glm::dvec3(lev::irradiance(l, x));
        }
        for (int c = 0; c < 3; ++c)
          ASSERT_GE(static_cast<double>(bound[c]), culled[c]) << "seed " << seed;
        if (tau == 0.0f) {
          ASSERT_EQ(radiance, rt.direct_radiance(point, scratch, counters)) << "seed " << seed;
        }
      }
    }
  }
}

TEST(LevEst, InTheMethodTable) {
  const std::optional<lev::Method> method = lev::parse_method("lev_est");
  ASSERT_TRUE(method.has_value());
  EXPECT_TRUE(lev::method_info(*method).uses_tolerance);
  EXPECT_FALSE(lev::method_info(*method).stochastic);
}

}  // namespace
