#include "lev/extent_volume.h"

#include <cmath>

#include <gtest/gtest.h>

#include "lev/light.h"

namespace {

TEST(ExtentVolume, PointLightBoundaryIrradianceEqualsTolerance) {
  const lev::Light light = lev::make_point_light({1.0f, 2.0f, 3.0f}, {4.0f, 2.0f, 1.0f});
  for (float tau : {1e-4f, 0.01f, 0.5f, 3.0f}) {
    const float r = lev::extent_radius(lev::strength(light), tau);
    EXPECT_FLOAT_EQ(r, std::sqrt(4.0f / tau));
    const glm::vec3 on_boundary = light.position + glm::vec3(0.0f, r, 0.0f);
    EXPECT_NEAR(lev::strength(light) * lev::irradiance_falloff(light, on_boundary), tau, tau * 1e-5f);
    const glm::vec3 outside = light.position + glm::vec3(0.0f, r * 1.001f, 0.0f);
    EXPECT_LT(lev::strength(light) * lev::irradiance_falloff(light, outside), tau);
    EXPECT_FALSE(lev::is_important(light, outside, tau));
    EXPECT_TRUE(lev::is_important(light, light.position + glm::vec3(0.0f, r * 0.999f, 0.0f), tau));
    const lev::Bounds b = lev::light_extent_bounds(light, tau);
    EXPECT_TRUE(lev::contains(b, on_boundary));
    EXPECT_FALSE(lev::contains(b, light.position + glm::vec3(r * 1.01f, 0.0f, 0.0f)));
  }
}

TEST(ExtentVolume, ToleranceZeroIsUnbounded) {
  const lev::Light light = lev::make_point_light({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
  EXPECT_TRUE(std::isinf(lev::extent_radius(1.0f, 0.0f)));
  const lev::Bounds b = lev::light_extent_bounds(light, 0.0f);
  EXPECT_TRUE(lev::contains(b, {1e30f, -1e30f, 3e38f}));
  EXPECT_TRUE(lev::is_important(light, {1e18f, 0.0f, 0.0f}, 0.0f));
}

TEST(ExtentVolume, DarkLightHasEmptyVolume) {
  const lev::Light light = lev::make_point_light({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
  EXPECT_TRUE(lev::is_empty(lev::light_extent_bounds(light, 0.01f)));
  EXPECT_FALSE(lev::is_important(light, {0.1f, 0.0f, 0.0f}, 0.0f));
}

TEST(ExtentVolume, LightOnTheQueryPointIsFiniteAndImportant) {
  const lev::Light light = lev::make_point_light({5.0f, 5.0f, 5.0f}, {1.0f, 1.0f, 1.0f});
  const float e = lev::irradiance_falloff(light, light.position);
  EXPECT_TRUE(std::isfinite(e));
  EXPECT_GT(e, 0.0f);
  EXPECT_TRUE(lev::is_important(light, light.position, 0.01f));
  const lev::Light spot = lev::make_spot_light({0, 0, 0}, {0, 0, -1}, {1, 1, 1}, 0.3f, 5.0f);
  EXPECT_TRUE(std::isfinite(lev::irradiance_falloff(spot, spot.position)));
}

TEST(ExtentVolume, SpotConeEdges) {
  const float half_angle = 0.5f;  // radians
  const lev::Light spot = lev::make_spot_light({0, 0, 10}, {0, 0, -1}, {100, 100, 100}, half_angle, 0.0f);
  const float d = 5.0f;
  const glm::vec3 inside = spot.position + d * glm::vec3(std::sin(half_angle - 0.01f), 0.0f, -std::cos(half_angle - 0.01f));
  const glm::vec3 outside = spot.position + d * glm::vec3(std::sin(half_angle + 0.01f), 0.0f, -std::cos(half_angle + 0.01f));
  EXPECT_TRUE(lev::is_important(spot, inside, 0.01f));
  EXPECT_FALSE(lev::is_important(spot, outside, 0.0f));
  EXPECT_EQ(lev::irradiance_falloff(spot, outside), 0.0f);
  // Behind the light: never lit by a cone narrower than 90 degrees.
  EXPECT_FALSE(lev::is_important(spot, spot.position + glm::vec3(0, 0, 1), 0.0f));
  // The box is tight along the axis and contains the cone's rim at full radius.
  const float tau = 0.01f;
  const float r = lev::extent_radius(100.0f, tau);
  const lev::Bounds b = lev::light_extent_bounds(spot, tau);
  EXPECT_NEAR(b.lo.z, 10.0f - r, 1e-3f);
  EXPECT_NEAR(b.hi.z, 10.0f, 1e-3f);
  EXPECT_NEAR(b.hi.x, r * std::sin(half_angle), 1e-2f);
  const glm::vec3 rim = spot.position + 0.999f * r * glm::vec3(std::sin(half_angle - 1e-3f), 0.0f, -std::cos(half_angle - 1e-3f));
  EXPECT_TRUE(lev::contains(b, rim));
  EXPECT_TRUE(lev::is_important(spot, rim, tau));
}

TEST(ExtentVolume, SpotDropoffFollowsWarn) {
  const lev::Light spot = lev::make_spot_light({0, 0, 0}, {1, 0, 0}, {1, 1, 1}, 1.2f, 4.0f);
  const float gamma = 0.6f;
  const glm::vec3 x = 2.0f * glm::vec3(std::cos(gamma), std::sin(gamma), 0.0f);
  EXPECT_NEAR(lev::irradiance_falloff(spot, x), std::pow(std::cos(gamma), 4.0f) / 4.0f, 1e-6f);
}

TEST(ExtentVolume, ExtentBoxContainsEveryImportantPoint) {
  // Sampled check of the cone-cut-by-sphere box for many directions and angles.
  std::uint64_t seed = 12345;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(seed >> 40) / static_cast<float>(1ull << 24);
  };
  for (int light_index = 0; light_index < 50; ++light_index) {
    const glm::vec3 dir = glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
    const float angle = 3.1f * uniform();
    const lev::Light spot = lev::make_spot_light({1, 2, 3}, dir, {5, 5, 5}, angle, 2.0f * uniform());
    const float tau = 0.05f;
    const lev::Bounds b = lev::light_extent_bounds(spot, tau);
    for (int k = 0; k < 2000; ++k) {
      const glm::vec3 x = spot.position + 12.0f * glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
      if (lev::is_important(spot, x, tau)) {
        ASSERT_TRUE(lev::contains(b, x)) << "light " << light_index;
      }
    }
  }
}

}  // namespace
