// The smooth glTF spot profile (lev/spot_profile.h) and a light's range: the falloff against the
// extension's formula, zero irradiance beyond the range, and brute-force checks that the extent
// box holds every point is_important accepts, at tolerance 0 too (where the range alone bounds it).
#include "lev/spot_profile.h"

#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "lev/extent_volume.h"
#include "lev/light.h"

namespace {

struct Uniform {
  std::uint64_t seed;
  float operator()() {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(seed >> 40) / static_cast<float>(1ull << 24);
  }
};

// KHR_lights_punctual's recommended implementation, in double.
double spec_attenuation(double cos_gamma, double inner, double outer) {
  const double scale = 1.0 / std::max(0.001, std::cos(inner) - std::cos(outer));
  const double offset = -std::cos(outer) * scale;
  const double t = std::clamp(cos_gamma * scale + offset, 0.0, 1.0);
  return t * t;
}

TEST(SpotProfile, SmoothFalloffFollowsTheExtensionsFormula) {
  const double inner = 18.0 * M_PI / 180.0, outer = 30.0 * M_PI / 180.0;
  const glm::vec3 intensity(2.0f, 3.0f, 4.0f);
  const lev::Light spot = lev::make_smooth_spot_light(
      {1, 2, 3}, {0, -1, 0}, intensity, static_cast<float>(inner), static_cast<float>(outer));
  int ramp_points = 0;
  for (int k = 0; k <= 400; ++k) {
    const double gamma = 40.0 * M_PI / 180.0 * k / 400.0;
    const double d = 2.5;
    const glm::vec3 x =
        spot.position + static_cast<float>(d) * glm::vec3(std::sin(gamma), -std::cos(gamma), 0.0);
    const double expected = spec_attenuation(std::cos(gamma), inner, outer) / (d * d);
    EXPECT_NEAR(lev::irradiance_falloff(spot, x), expected, 1e-4 * (expected + 1e-3))
        << "gamma " << gamma;
    if (gamma > inner + 1e-3 && gamma < outer - 1e-3) {
      ++ramp_points;
      EXPECT_GT(expected, 0.0);
      EXPECT_LT(expected, 1.0 / (d * d));
    }
  }
  EXPECT_GT(ramp_points, 50);
  // Full inside the inner cone, dark beyond the outer one.
  EXPECT_FLOAT_EQ(lev::smooth_spot_attenuation(1.0f, spot.cos_cone_half_angle, spot.cos_inner_cone),
                  1.0f);
  EXPECT_EQ(
      lev::smooth_spot_attenuation(std::cos(0.6f), spot.cos_cone_half_angle, spot.cos_inner_cone),
      0.0f);
}

TEST(SpotProfile, RangeDarkensEveryLightBeyondIt) {
  lev::Light point = lev::make_point_light({0, 0, 0}, {5, 5, 5});
  point.range = 4.0f;
  EXPECT_GT(lev::irradiance_falloff(point, {3.99f, 0, 0}), 0.0f);
  EXPECT_EQ(lev::irradiance_falloff(point, {4.01f, 0, 0}), 0.0f);
  EXPECT_FALSE(lev::is_important(point, {0, 4.01f, 0}, 0.0f));
  lev::Light spot = lev::make_smooth_spot_light({0, 0, 0}, {1, 0, 0}, {5, 5, 5}, 0.2f, 0.4f);
  spot.range = 2.0f;
  EXPECT_GT(lev::irradiance_falloff(spot, {1.99f, 0, 0}), 0.0f);
  EXPECT_EQ(lev::irradiance_falloff(spot, {2.01f, 0, 0}), 0.0f);
  // Seen through a scale the range scales with the distances, so irradiance is unchanged.
  const lev::Similarity xf = lev::compose(lev::make_translation({1, 2, 3}), lev::make_scale(3.0f));
  const lev::Light moved = lev::transform_light(point, xf);
  EXPECT_FLOAT_EQ(moved.range, 12.0f);
  EXPECT_GT(lev::irradiance_falloff(moved, lev::apply_point(xf, {3.9f, 0, 0})), 0.0f);
  EXPECT_EQ(lev::irradiance_falloff(moved, lev::apply_point(xf, {4.1f, 0, 0})), 0.0f);
}

// Random smooth and Warn spots and point lights, with and without a range, at tolerances
// including 0: every point is_important accepts lies in the box, and a range bounds the box.
TEST(SpotProfile, ExtentBoxHoldsEveryImportantPointAndNeverExceedsTheRange) {
  Uniform uniform{424242};
  int important = 0;
  const float tolerances[] = {0.0f, 0.001f, 0.02f, 0.3f};
  for (int light_index = 0; light_index < 240; ++light_index) {
    const glm::vec3 axis =
        glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
    const glm::vec3 position(10.0f * uniform(), -5.0f * uniform(), 3.0f);
    const glm::vec3 intensity(2.0f, 5.0f * uniform(), 1.0f);
    lev::Light light;
    switch (light_index % 3) {
      case 0: {
        const float outer = 0.05f + 1.5f * uniform();
        light = lev::make_smooth_spot_light(position, axis, intensity, outer * uniform(), outer);
        break;
      }
      case 1:
        light =
            lev::make_spot_light(position, axis, intensity, 3.0f * uniform(), 20.0f * uniform());
        break;
      default:
        light = lev::make_point_light(position, intensity);
        break;
    }
    if (light_index % 2 == 0) light.range = 0.5f + 20.0f * uniform();
    const float tau = tolerances[light_index % 4];
    const lev::Bounds b = lev::light_extent_bounds(light, tau);
    if (std::isfinite(light.range)) {
      for (int i = 0; i < 3; ++i) {
        EXPECT_LE(b.hi[i] - position[i], light.range * 1.001f);
        EXPECT_LE(position[i] - b.lo[i], light.range * 1.001f);
      }
    }
    const float reach = std::isfinite(light.range) ? light.range : 30.0f;
    for (int k = 0; k < 4000; ++k) {
      glm::vec3 x;
      if (k % 2 == 0) {
        x = position +
            2.2f * reach * glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
      } else {  // crowded at the range's sphere
        const glm::vec3 u =
            glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
        x = position + (0.999f + 0.002f * uniform()) * reach * u;
      }
      if (lev::is_important(light, x, tau)) {
        ++important;
        ASSERT_TRUE(lev::contains(b, x)) << "light " << light_index << " tolerance " << tau;
      }
    }
  }
  EXPECT_GT(important, 10000);
}

}  // namespace
