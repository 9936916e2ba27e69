// `lev_bounded`'s walk (find_lights_within_budget) on random instanced scenes: at every point the
// culled bound stays within the tolerance and still bounds the irradiance of every light not
// returned; it returns at least the lights `lev` returns, in the same order; at tolerance 0 it
// returns what `rt` tests; the same call gives the same lights.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

using lev_test::same_light_placement;

TEST(LevBounded, CulledBoundWithinTheToleranceAndAboveWhatWasCulled) {
  std::uint64_t bounded_points = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    lev::WalkScratch scratch;
    for (const float tau : {1e-3f, 1e-2f, 0.1f, 1.0f, 1e30f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      for (int k = 0; k < 60; ++k) {
        const glm::vec3 x(r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-15, 15));
        const std::string context = "seed " + std::to_string(seed) + " tau " + std::to_string(tau) +
                                    " k " + std::to_string(k);
        std::vector<lev::Light> bounded, again, plain;
        lev::WalkCounters counters;
        glm::vec3 culled, culled_again;
        lev::find_lights_within_budget(h, volumes, tau, x, scratch, bounded, counters, &culled);
        lev::find_lights_within_budget(h, volumes, tau, x, scratch, again, counters, &culled_again);
        lev_test::expect_same_lights(again, bounded, context);
        ASSERT_EQ(culled, culled_again) << context;
        ASSERT_LE(std::max(std::max(culled.x, culled.y), culled.z), tau) << context;
        // Still a bound of what was not returned.
        glm::dvec3 exact(0.0);
        for (const lev::Light& l : world_lights) {
          const bool returned =
              std::any_of(bounded.begin(), bounded.end(),
                          [&](const lev::Light& b) { return same_light_placement(b, l); });
          if (!returned) exact += glm::dvec3(lev::irradiance(l, x));
        }
        for (int c = 0; c < 3; ++c) ASSERT_GE(static_cast<double>(culled[c]), exact[c]) << context;
        // lev's lights are a subsequence of lev_bounded's.
        lev::find_important_lights(h, volumes, tau, x, scratch, plain, counters);
        std::size_t next = 0;
        for (const lev::Light& l : bounded) {
          if (next < plain.size() && same_light_placement(l, plain[next])) ++next;
        }
        ASSERT_EQ(next, plain.size()) << context;
        if (bounded.size() > plain.size()) ++bounded_points;
      }
    }
  }
  // The budget made a difference at many points: it is not lev under another name.
  EXPECT_GT(bounded_points, 500u);
}

TEST(LevBounded, AtToleranceZeroSelectsWhatRtTests) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> flat = lev::flatten_lights(h);
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, 0.0f);
    lev::WalkScratch scratch;
    for (int k = 0; k < 40; ++k) {
      const glm::vec3 x(r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-15, 15));
      std::vector<lev::Light> bounded;
      lev::WalkCounters counters;
      glm::vec3 culled;
      lev::find_lights_within_budget(h, volumes, 0.0f, x, scratch, bounded, counters, &culled);
      lev_test::expect_same_lights(bounded, lev::important_lights_brute_force(flat, x, 0.0f),
                                   "seed " + std::to_string(seed));
      ASSERT_EQ(culled, glm::vec3(0.0f));
    }
  }
}

TEST(LevBounded, InTheMethodTable) {
  const std::optional<lev::Method> method = lev::parse_method("lev_bounded");
  ASSERT_TRUE(method.has_value());
  EXPECT_TRUE(lev::method_info(*method).uses_tolerance);
}

}  // namespace
