#include "lev/extent_volume.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "lev/light.h"

namespace {

TEST(ExtentVolume, PointLightBoundaryIrradianceEqualsTolerance) {
  const lev::Light light = lev::make_point_light({1.0f, 2.0f, 3.0f}, {4.0f, 2.0f, 1.0f});
  for (float tau : {1e-4f, 0.01f, 0.5f, 3.0f}) {
    const float r = lev::extent_radius(lev::strength(light), tau);
    EXPECT_FLOAT_EQ(r, std::sqrt(4.0f / tau));
    const glm::vec3 on_boundary = light.position + glm::vec3(0.0f, r, 0.0f);
    EXPECT_NEAR(lev::strength(light) * lev::irradiance_falloff(light, on_boundary), tau,
                tau * 1e-5f);
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
  const lev::Light spot =
      lev::make_spot_light({0, 0, 10}, {0, 0, -1}, {100, 100, 100}, half_angle, 0.0f);
  const float d = 5.0f;
  const glm::vec3 inside = spot.position + d * glm::vec3(std::sin(half_angle - 0.01f), 0.0f,
                                                         -std::cos(half_angle - 0.01f));
  const glm::vec3 outside = spot.position + d * glm::vec3(std::sin(half_angle + 0.01f), 0.0f,
                                                          -std::cos(half_angle + 0.01f));
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
  const glm::vec3 rim =
      spot.position +
      0.999f * r * glm::vec3(std::sin(half_angle - 1e-3f), 0.0f, -std::cos(half_angle - 1e-3f));
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
    const glm::vec3 dir =
        glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
    const float angle = 3.1f * uniform();
    const lev::Light spot =
        lev::make_spot_light({1, 2, 3}, dir, {5, 5, 5}, angle, 2.0f * uniform());
    const float tau = 0.05f;
    const lev::Bounds b = lev::light_extent_bounds(spot, tau);
    for (int k = 0; k < 2000; ++k) {
      const glm::vec3 x =
          spot.position + 12.0f * glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
      if (lev::is_important(spot, x, tau)) {
        ASSERT_TRUE(lev::contains(b, x)) << "light " << light_index;
      }
    }
  }
}

// Warn's dropoff bounds the lit region more tightly than the cone cut by the sphere: along a
// direction at gamma from the axis it ends at r cos(gamma)^(P/2). spot_extent_reach is the box
// face that region gives; compare it with a dense scan over gamma (and the closed form at P = 0).
TEST(ExtentVolume, SpotExtentReachMatchesAScanOverTheCone) {
  for (double dropoff : {0.0, 0.3, 1.0, 2.0, 7.5, 100.0, 1e4}) {
    for (double delta :
         {0.05, 0.5, 1.0471975511965976, 1.5, 1.5707963267948966, 2.0, 3.1415926535897931}) {
      for (int t = 0; t <= 40; ++t) {
        const double theta = M_PI * t / 40.0;
        // The largest projection on e of r cos(gamma)^(P/2) u over the directions u in the cone
        // (and the apex, 0): for each gamma the best u lies in the plane of the axis and e.
        const double top = dropoff > 0.0 ? std::min(delta, M_PI / 2.0) : delta;
        const auto projection = [&](double gamma) {
          const double along = std::cos(std::abs(theta - gamma));
          return (dropoff > 0.0 ? std::pow(std::cos(gamma), 0.5 * dropoff) : 1.0) * along;
        };
        // A coarse scan, then a fine one around its best step.
        double scanned = 0.0, best = 0.0;
        const double step = top / 4000.0;
        for (int k = 0; k <= 4000; ++k) {
          if (projection(step * k) > scanned) scanned = projection(best = step * k);
        }
        for (int k = -4000; k <= 4000; ++k) {
          const double gamma = std::clamp(best + step * k / 4000.0, 0.0, top);
          scanned = std::max(scanned, projection(gamma));
        }
        const double reach = lev::spot_extent_reach(theta, delta, dropoff);
        // (cos(pi / 2) is 6e-17 in double, not 0: the scan's tail at the rim is rounding.)
        EXPECT_GE(reach, scanned - 1e-15)
            << "P " << dropoff << " delta " << delta << " theta " << theta;
        EXPECT_LE(reach, scanned + 1e-6)
            << "P " << dropoff << " delta " << delta << " theta " << theta;
        if (dropoff == 0.0) {
          EXPECT_NEAR(reach, std::max(0.0, std::cos(std::max(0.0, theta - delta))), 1e-12);
        }
      }
    }
  }
}

TEST(ExtentVolume, SpotDropoffShrinksTheBoxSideways) {
  // The hall's spots: 60 degrees, P = 1. Sideways the cone cut by the sphere reaches r sin 60
  // = 0.866 r; with the dropoff the farthest lit point sideways is at tan^2(gamma) = 2, reaching
  // r sqrt(cos gamma) sin gamma = 0.620 r. Along the axis nothing changes.
  const lev::Light spot = lev::make_spot_light({0, 0, 0}, {0, 0, -1}, {4, 4, 4}, 1.0471976f, 1.0f);
  const float tau = 0.01f;
  const float r = lev::extent_radius(4.0f, tau);
  const lev::Bounds b = lev::light_extent_bounds(spot, tau);
  const double gamma = std::atan(std::sqrt(2.0));
  const double side = std::sqrt(std::cos(gamma)) * std::sin(gamma);
  EXPECT_NEAR(b.hi.x, r * side, 1e-4f * r);
  EXPECT_NEAR(b.lo.y, -r * side, 1e-4f * r);
  EXPECT_NEAR(b.lo.z, -r, 1e-4f * r);
  EXPECT_NEAR(b.hi.z, 0.0f, 1e-6f * r);
  // The farthest lit point sideways is important, and just beyond the face nothing is.
  const glm::vec3 x =
      0.9999f * r * std::sqrt(static_cast<float>(std::cos(gamma))) *
      glm::vec3(static_cast<float>(std::sin(gamma)), 0.0f, -static_cast<float>(std::cos(gamma)));
  EXPECT_TRUE(lev::is_important(spot, x, tau));
  EXPECT_TRUE(lev::contains(b, x));
}

TEST(ExtentVolume, SpotDropoffBoxContainsEveryImportantPoint) {
  // Random spots (any axis, cones up to 180 degrees, dropoffs from 0 to large), points both
  // spread around the light and crowded at the edge of the exact volume: every point that
  // is_important accepts must be inside the box. And the box is tight: along each axis, the
  // farthest point of the exact volume (scanned in the plane of the spot axis and that axis) is
  // important and lies within 1% of the extent radius of the face.
  std::uint64_t seed = 987654321;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(seed >> 40) / static_cast<float>(1ull << 24);
  };
  const float dropoffs[] = {0.0f, 0.5f, 1.0f, 3.0f, 20.0f, 300.0f, 10000.0f};
  int important_total = 0;
  for (int light_index = 0; light_index < 140; ++light_index) {
    const glm::vec3 axis =
        glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
    const float angle = 3.14159f * uniform();
    const float dropoff = dropoffs[light_index % 7];
    const glm::vec3 position(10.0f * uniform(), -5.0f * uniform(), 3.0f);
    const lev::Light spot =
        lev::make_spot_light(position, axis, {2.0f, 5.0f, 1.0f}, angle, dropoff);
    const float tau = 0.02f;
    const float r = lev::extent_radius(lev::strength(spot), tau);
    const auto edge = [&](float cos_gamma) {  // distance to the exact volume's edge
      return dropoff > 0.0f ? r * std::pow(std::max(cos_gamma, 0.0f), 0.5f * dropoff) : r;
    };
    const lev::Bounds b = lev::light_extent_bounds(spot, tau);
    for (int k = 0; k < 6000; ++k) {
      glm::vec3 x;
      if (k % 2 == 0) {
        x = position + 2.2f * r * glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
      } else {
        // A direction in the cone, and a distance just inside or outside the exact edge.
        const glm::vec3 u =
            glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f));
        const float cos_gamma = glm::dot(u, spot.direction);
        if (cos_gamma < spot.cos_cone_half_angle) continue;
        x = position + (0.995f + 0.01f * uniform()) * edge(cos_gamma) * u;
      }
      if (!lev::is_important(spot, x, tau)) continue;
      ++important_total;
      ASSERT_TRUE(lev::contains(b, x))
          << "light " << light_index << " P " << dropoff << " cone " << angle;
    }
    for (int i = 0; i < 3; ++i) {
      for (float sign : {1.0f, -1.0f}) {
        glm::vec3 e(0.0f);
        e[i] = sign;
        glm::vec3 w = e - glm::dot(e, spot.direction) * spot.direction;
        w = glm::length(w) > 1e-6f
                ? glm::normalize(w)
                : glm::normalize(glm::cross(spot.direction, glm::vec3(0.3f, 0.5f, 0.8f)));
        float farthest = 0.0f;  // the apex
        for (int k = 0; k <= 4000; ++k) {
          const float gamma = std::acos(spot.cos_cone_half_angle) * static_cast<float>(k) / 4000.0f;
          const glm::vec3 u = std::cos(gamma) * spot.direction + std::sin(gamma) * w;
          const glm::vec3 x = position + 0.999f * edge(std::cos(gamma)) * u;
          if (!lev::is_important(spot, x, tau)) continue;
          farthest = std::max(farthest, sign * (x[i] - position[i]));
        }
        const float face = sign > 0.0f ? b.hi[i] - position[i] : position[i] - b.lo[i];
        EXPECT_GE(face, farthest) << "light " << light_index << " axis " << i;
        EXPECT_LT(face - farthest, 0.01f * r)
            << "light " << light_index << " axis " << i << " P " << dropoff;
      }
    }
  }
  EXPECT_GT(important_total, 100000);
}

}  // namespace
