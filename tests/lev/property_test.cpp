// Property tests over random light scenes (fixed seeds): the walk returns exactly the lights
// whose irradiance reaches the tolerance, for random points, tolerances, transforms and
// spotlights at the extremes of their parameters; an instanced scene agrees with its flattened
// twin.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "lev/extent_volume.h"
#include "lev/important_lights.h"
#include "lev/light_bvh.h"
#include "lev/light_hierarchy.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;
using lev_test::random_instanced_tree;

// The brute force runs over the tree's own flattening (flatten_light_description), which shares no
// code with build_hierarchy or the walk: the walk is checked against a second implementation.
TEST(Property, WalkNeverMissesAndNeverAddsALight) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> flat = lev::flatten_light_description(tree);
    ASSERT_EQ(flat.size(), h.light_count);
    lev::LightDescription twin;
    twin.root = lev::build_light_bvh(flat);
    const lev::LightHierarchy flattened = lev::build_hierarchy(twin);
    lev::WalkScratch scratch;
    for (int t = 0; t < 6; ++t) {
      const float tau = t == 0 ? 0.0f : std::pow(10.0f, r.uniform(-5.0f, 1.0f));
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      const lev::ExtentVolumes flattened_volumes = lev::fit_extent_volumes(flattened, tau);
      for (int k = 0; k < 40; ++k) {
        const glm::vec3 p(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
        std::vector<lev::Light> found, found_flat;
        lev::WalkCounters c1, c2;
        lev::find_important_lights(h, volumes, tau, p, scratch, found, c1);
        lev::find_important_lights(flattened, flattened_volumes, tau, p, scratch, found_flat, c2);
        const std::vector<lev::Light> expected = lev::important_lights_brute_force(flat, p, tau);
        lev_test::expect_same_lights(
            found, expected, "seed " + std::to_string(seed) + " tau " + std::to_string(tau));
        if (HasFatalFailure()) return;
        ASSERT_EQ(found_flat.size(), expected.size()) << "seed " << seed << " tau " << tau;
      }
    }
  }
}

// rt and ast shade the hierarchy's flattening (flatten_lights, the walk without culling): it is the
// tree's plain recursion, light for light and float for float.
TEST(Property, FlattenedHierarchyEqualsThePlainRecursion) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = random_instanced_tree(r);
    const std::vector<lev::Light> plain = lev::flatten_light_description(tree);
    ASSERT_FALSE(plain.empty());
    lev_test::expect_same_lights(lev::flatten_lights(lev::build_hierarchy(tree)), plain,
                                 "seed " + std::to_string(seed));
    if (HasFatalFailure()) return;
  }
}

TEST(Property, ExtremeTolerancesNeitherCrashNorProduceNaN) {
  Random r(99);
  const lev::LightDescription tree = random_instanced_tree(r);
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> flat = lev::flatten_light_description(tree);
  lev::WalkScratch scratch;
  const float tiny = std::numeric_limits<float>::denorm_min();
  for (float tau : {tiny, std::numeric_limits<float>::min(), 1e-30f, 1e30f,
                    std::numeric_limits<float>::max(), std::numeric_limits<float>::infinity()}) {
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
    for (const lev::FittedNode& node : volumes.nodes) {
      for (int a = 0; a < 3; ++a) {
        ASSERT_FALSE(std::isnan(node.volume.lo[a]) || std::isnan(node.volume.hi[a]))
            << "tau " << tau;
      }
    }
    for (int k = 0; k < 50; ++k) {
      const glm::vec3 p(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
      std::vector<lev::Light> found;
      lev::WalkCounters c;
      lev::find_important_lights(h, volumes, tau, p, scratch, found, c);
      EXPECT_EQ(found.size(), lev::important_lights_brute_force(flat, p, tau).size())
          << "tau " << tau;
      if (tau >= 1e30f) {
        EXPECT_TRUE(found.empty());
      }
    }
  }
}

TEST(Property, ExtremeIntensitiesStayFinite) {
  for (float intensity :
       {0.0f, 1e-30f, 1e-10f, 1.0f, 1e10f, 1e30f, std::numeric_limits<float>::max()}) {
    const lev::Light l = lev::make_point_light({0, 0, 0}, glm::vec3(intensity, 0.0f, intensity));
    for (float d : {0.0f, 1e-20f, 1e-6f, 1.0f, 1e6f, 1e19f}) {
      const glm::vec3 e = lev::irradiance(l, {d, 0, 0});
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(e[c])) << intensity << " at " << d;
        EXPECT_GE(e[c], 0.0f);
      }
    }
    const float r = lev::extent_radius(intensity, 0.01f);
    EXPECT_FALSE(std::isnan(r));
    if (intensity == 0.0f) {
      EXPECT_EQ(r, 0.0f);
      EXPECT_FALSE(lev::is_important(l, {1, 0, 0}, 0.0f));  // a dark light is never tested
    }
  }
}

TEST(Property, DegenerateSpotsKeepConservativeVolumes) {
  Random r(5);
  for (float angle : {0.0f, 1e-6f, 1e-3f, 1.5707964f, 3.1415927f}) {
    for (float dropoff : {0.0f, 1.0f, 10000.0f}) {
      const lev::Light spot =
          lev::make_spot_light({1, 2, 3}, r.direction(), {2, 2, 2}, angle, dropoff);
      for (float tau : {1e-4f, 0.01f, 1.0f}) {
        const lev::Bounds b = lev::light_extent_bounds(spot, tau);
        ASSERT_FALSE(std::isnan(b.lo.x) || std::isnan(b.hi.x));
        // Points on and near the axis, where a narrow cone still lights.
        for (int k = 0; k < 2000; ++k) {
          const glm::vec3 p =
              spot.position +
              r.uniform(0.0f, 30.0f) *
                  glm::normalize(spot.direction + r.uniform(0.0f, 0.01f) * r.direction());
          if (lev::is_important(spot, p, tau)) {
            ASSERT_TRUE(lev::contains(b, p))
                << "angle " << angle << " dropoff " << dropoff << " tau " << tau;
          }
          const float e = lev::irradiance_falloff(spot, p);
          ASSERT_TRUE(std::isfinite(e) && e >= 0.0f);
        }
      }
    }
  }
}

}  // namespace
