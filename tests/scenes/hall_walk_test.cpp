// The hall's light hierarchy as the walk sees it: the grouping of the rig (blocks and quadrants)
// and the fixtures built by pure translations must change which volumes are checked, never which
// lights are returned; and a point out of every light's reach (the stage, far below the weak
// lights of the top level) must cost a handful of box tests, not one per fixture.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/hall.h"

namespace {

bool same_lights(const std::vector<lev::Light>& a, const std::vector<lev::Light>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].position != b[i].position || a[i].intensity != b[i].intensity ||
        a[i].direction != b[i].direction) {
      return false;
    }
  }
  return true;
}

TEST(HallWalk, ReturnsExactlyTheImportantLightsAroundTheRig) {
  std::uint64_t seed = 4242;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(seed >> 40) / static_cast<float>(1ull << 24);
  };
  for (int level : {3, 5, 7}) {
    renderer::Scene scene = scenes::build_hall(level);
    const std::vector<lev::Light> all = lev::flatten_lights(scene.lights);
    for (float tolerance : {0.001f, 0.01f, 0.1f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.lights, tolerance);
      lev::WalkScratch scratch;
      for (int k = 0; k < 400; ++k) {
        // Most points in the slab of the rig, where the spots' volumes crowd, the rest anywhere.
        const float z =
            k % 4 == 0 ? 13.5f * uniform() : scenes::kRigHeight + 3.0f * (uniform() - 0.5f);
        const glm::vec3 p(32.0f * uniform() - 16.0f, 39.0f * uniform() - 22.0f, z);
        std::vector<lev::Light> walked;
        lev::WalkCounters counters;
        lev::find_important_lights(scene.lights, volumes, tolerance, p, scratch, walked, counters);
        ASSERT_TRUE(same_lights(walked, lev::important_lights_brute_force(all, p, tolerance)))
            << "level " << level << " tolerance " << tolerance << " point " << p.x << " " << p.y
            << " " << p.z;
      }
    }
  }
}

TEST(HallWalk, StageBelowTheReachOfWeakLightsCostsAFewBoxTests) {
  renderer::Scene scene = scenes::build_hall(7);
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.lights, 0.01f);
  lev::WalkScratch scratch;
  for (const glm::vec3 p :
       {glm::vec3(0.0f, 5.0f, 0.8f), glm::vec3(-4.0f, 3.0f, 0.8f), glm::vec3(3.0f, 8.0f, 0.8f)}) {
    std::vector<lev::Light> walked;
    lev::WalkCounters counters;
    lev::find_important_lights(scene.lights, volumes, 0.01f, p, scratch, walked, counters);
    EXPECT_TRUE(walked.empty());
    EXPECT_LE(counters.nodes_visited, 4u) << "the four quadrants of the rig";
  }
}

}  // namespace
