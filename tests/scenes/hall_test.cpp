#include "scenes/hall.h"

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_models.h"

namespace {

TEST(Hall, LightCountsPerLevel) {
  const std::uint64_t expected[] = {64, 256, 1024, 4096, 16384};
  for (int level = 3; level <= 7; ++level) {
    EXPECT_EQ(scenes::hall_light_count(level), expected[level - 3]);
    const renderer::Scene scene = scenes::build_hall(level);
    EXPECT_EQ(scene.lights.light_count, expected[level - 3]);
    EXPECT_EQ(lev::flatten_lights(scene.lights).size(), expected[level - 3]);
  }
  const scenes::SceneModel* model = scenes::find_scene_model("hall");
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(scenes::level_for_light_count(*model, 16384), 7);
  EXPECT_EQ(scenes::level_for_light_count(*model, 16), -1);
}

TEST(Hall, HierarchyGrowsByAConstantPerLevel) {
  std::vector<std::size_t> bytes;
  for (int level = 3; level <= 8; ++level)
    bytes.push_back(lev::hierarchy_bytes(scenes::build_hall(level).lights));
  const std::size_t step = bytes[2] - bytes[1];
  EXPECT_GT(step, 0u);
  for (std::size_t i = 2; i < bytes.size(); ++i)
    EXPECT_EQ(bytes[i] - bytes[i - 1], step) << "level " << i + 3;
  EXPECT_LT(bytes.back(), 16u * 1024u);
}

TEST(Hall, EachSplitQuartersTheIntensityAndKeepsTheTotal) {
  for (int level = 3; level <= 6; ++level) {
    const std::vector<lev::Light> lights = lev::flatten_lights(scenes::build_hall(level).lights);
    const float quarter = scenes::kSpotIntensity / static_cast<float>(1 << (2 * (level - 3)));
    glm::vec3 total(0.0f);
    for (const lev::Light& l : lights) {
      EXPECT_EQ(l.kind, lev::LightKind::spot);
      EXPECT_NEAR(lev::strength(l), quarter, 1e-4f * quarter);
      EXPECT_NEAR(l.position.z, scenes::kRigHeight, 2.0f);  // clusters tilt with their aim
      total += l.intensity;
    }
    EXPECT_NEAR(total.x, 64.0f * scenes::kSpotIntensity, 1e-3f * total.x) << "level " << level;
  }
}

// The thesis' point about this model (5.4.2.2): every spot on the stage is lit by most lights,
// and once the lights are many, each is below the tolerance.
TEST(Hall, MostLightsReachTheStageAndManyFallBelowTheTolerance) {
  for (int level : {3, 5, 7}) {
    const std::vector<lev::Light> lights = lev::flatten_lights(scenes::build_hall(level).lights);
    for (const glm::vec3 p :
         {glm::vec3(0.0f, 5.0f, 0.8f), glm::vec3(-4.0f, 3.0f, 0.8f), glm::vec3(3.0f, 8.0f, 0.8f)}) {
      std::size_t reaching = 0, important = 0;
      for (const lev::Light& l : lights) {
        reaching += lev::irradiance_falloff(l, p) > 0.0f ? 1 : 0;
        important += lev::is_important(l, p, 0.01f) ? 1 : 0;
      }
      EXPECT_GT(reaching, lights.size() * 7 / 10) << "level " << level;
      if (level == 3) {
        EXPECT_EQ(important, reaching);
      }
      if (level == 7) {
        EXPECT_LT(important, reaching / 100);
      }
    }
  }
}

TEST(Hall, RejectsLevelsOutOfRange) {
  EXPECT_THROW(scenes::describe_hall(2), std::invalid_argument);
  EXPECT_THROW(scenes::describe_hall(scenes::kHallMaxLevel + 1), std::invalid_argument);
}

}  // namespace
