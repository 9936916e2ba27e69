// The light aggregates and the walk's culled bound on the scene models: instanced, the building
// keeps its hierarchy (aggregates included) under 8 KB at 65,536 lights; in the building, the maze
// and the hall the culled bound is never below the irradiance of the lights the walk culled, at
// points all over each scene, and it is finite at many of them (infinite only near the lights).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/hierarchy_cursor.h"
#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_instantiation.h"
#include "scenes/scene_models.h"

namespace {

TEST(SceneLightBounds, InstancedBuildingOf65536LightsStaysUnder8KB) {
  const scenes::SceneModel* building = scenes::find_scene_model("building");
  ASSERT_NE(building, nullptr);
  const renderer::Scene scene = scenes::instantiate_scene(building->describe(8));
  ASSERT_EQ(scene.lights.light_count, 65536u);
  const std::size_t aggregate_bytes = scene.lights.aggregates.size() * sizeof(lev::LightAggregate);
  EXPECT_GT(aggregate_bytes, 0u);
  EXPECT_LT(lev::hierarchy_bytes(scene.lights), 8u * 1024u);
  // The root's aggregate sums every light of the building (one intensity, 65,536 rooms).
  const lev::LightAggregate* all = lev::stored_aggregate(scene.lights, scene.lights.root);
  ASSERT_NE(all, nullptr);
  const std::vector<lev::Light> lights = lev::flatten_lights(scene.lights);
  double sum = 0.0;
  for (const lev::Light& l : lights) sum += l.intensity.x;
  EXPECT_GE(static_cast<double>(all->intensity.x), sum);
  EXPECT_LE(static_cast<double>(all->intensity.x), sum * (1.0 + 1e-5));
}

TEST(SceneLightBounds, CulledBoundHoldsAllOverEveryModel) {
  std::uint64_t state = 99;
  auto uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state >> 40) / static_cast<float>(1ull << 24);
  };
  for (const auto& [name, level] :
       {std::pair<const char*, int>{"building", 4}, {"maze", 2}, {"hall", 5}}) {
    const scenes::SceneModel* model = scenes::find_scene_model(name);
    ASSERT_NE(model, nullptr);
    const renderer::Scene scene = scenes::instantiate_scene(model->describe(level));
    const std::vector<lev::Light> all = lev::flatten_lights(scene.lights);
    const lev::LightAggregate* root = lev::stored_aggregate(scene.lights, scene.lights.root);
    ASSERT_NE(root, nullptr);
    const glm::vec3 lo = root->positions.lo - 2.0f, extent = root->positions.hi + 2.0f - lo;
    std::uint64_t finite = 0;
    for (const float tolerance : {0.001f, 0.01f, 0.1f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.lights, tolerance);
      lev::WalkScratch scratch;
      for (int k = 0; k < 300; ++k) {
        const glm::vec3 x = lo + extent * glm::vec3(uniform(), uniform(), uniform());
        std::vector<lev::Light> walked;
        lev::WalkCounters counters;
        glm::vec3 bound;
        lev::find_important_lights(scene.lights, volumes, tolerance, x, scratch, walked, counters,
                                   &bound);
        glm::dvec3 exact(0.0);
        for (const lev::Light& l : all) {
          if (!lev::is_important(l, x, tolerance)) exact += glm::dvec3(lev::irradiance(l, x));
        }
        for (int c = 0; c < 3; ++c) {
          ASSERT_GE(static_cast<double>(bound[c]), exact[c])
              << name << " tolerance " << tolerance << " x " << x.x << " " << x.y << " " << x.z;
        }
        if (std::isfinite(bound.x) && exact.x > 0.0) ++finite;
      }
    }
    EXPECT_GT(finite, 300u) << name;
  }
}

}  // namespace
