// The light aggregates on the scene models: instanced, the building keeps its hierarchy
// (aggregates included) under 8 KB at 65,536 lights.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

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

}  // namespace
