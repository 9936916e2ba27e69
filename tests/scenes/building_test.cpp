#include "scenes/building.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_models.h"

namespace {

// Floors placed in the scene: each room has one floor quad (two triangles of material 0).
std::uint64_t placed_rooms(const renderer::Scene& scene) {
  std::uint64_t rooms = 0;
  for (const renderer::PlacedPrototype& placed : scene.geometry.instances) {
    for (const renderer::TriangleMesh& mesh : scene.geometry.prototypes[placed.prototype].meshes) {
      if (mesh.material == 0) rooms += mesh.triangles.size() / 2;
    }
  }
  return rooms;
}

TEST(Building, LightCountsPerLevel) {
  const std::uint64_t expected[] = {4, 16, 64, 256, 1024, 4096, 16384, 65536, 262144, 1048576};
  for (int level = 1; level <= 10; ++level)
    EXPECT_EQ(scenes::building_light_count(level), expected[level - 1]);
  for (int level = 1; level <= 7; ++level) {
    const renderer::Scene scene = scenes::build_building(level);
    EXPECT_EQ(scene.lights.light_count, expected[level - 1]);
    EXPECT_EQ(lev::flatten_lights(scene.lights).size(), expected[level - 1]);
    EXPECT_EQ(placed_rooms(scene), expected[level - 1]);
    // Rooms are baked into prototypes of up to 16 (scene_instantiation.h), so far fewer Embree
    // instances than rooms.
    EXPECT_LE(scene.geometry.instances.size() * 16,
              std::max<std::uint64_t>(16, expected[level - 1]));
  }
  const scenes::SceneModel* model = scenes::find_scene_model("building");
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(scenes::level_for_light_count(*model, 16384), 7);
  EXPECT_EQ(scenes::level_for_light_count(*model, 1000), -1);
}

TEST(Building, HierarchyGrowsByAConstantPerLevel) {
  std::vector<std::size_t> bytes;
  for (int level = 1; level <= 8; ++level)
    bytes.push_back(lev::hierarchy_bytes(scenes::build_building(level).lights));
  const std::size_t step = bytes[1] - bytes[0];
  EXPECT_GT(step, 0u);
  for (std::size_t i = 1; i < bytes.size(); ++i)
    EXPECT_EQ(bytes[i] - bytes[i - 1], step) << "level " << i + 1;
  EXPECT_LT(bytes.back(), 16u * 1024u);
}

TEST(Building, EveryLightSitsUnderTheCeilingOfItsRoom) {
  const renderer::Scene scene = scenes::build_building(3);
  for (const lev::Light& l : lev::flatten_lights(scene.lights)) {
    EXPECT_FLOAT_EQ(l.position.z, scenes::kCeilingLightHeight);
    EXPECT_FLOAT_EQ(std::fmod(l.position.x, scenes::kRoomSize), 0.5f * scenes::kRoomSize);
    EXPECT_FLOAT_EQ(std::fmod(l.position.y, scenes::kRoomSize), 0.5f * scenes::kRoomSize);
  }
}

TEST(Building, RejectsLevelsOutOfRange) {
  EXPECT_THROW(scenes::build_building(0), std::invalid_argument);
  EXPECT_THROW(scenes::build_building(11), std::invalid_argument);
}

}  // namespace
