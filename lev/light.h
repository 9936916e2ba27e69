// Point lights and Warn spotlights (thesis 2.2, eq. 1-6) and their unshadowed irradiance.
// The same struct describes a light in its own frame (inside the hierarchy) and in world space
// (what a query returns); transform_light maps one to the other. Imported glTF lights add two
// things the thesis' lights lack: a range beyond which a light is dark, and the smooth spot
// profile (spot_profile.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "lev/spot_profile.h"
#include "lev/transform.h"

namespace lev {

enum class LightKind : std::uint8_t { point, spot };

struct Light {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{1.0f};               // RGB, irradiance at distance 1 on the axis
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot axis (unit)
  float cos_cone_half_angle = -1.0f;  // spot: lit where cos(gamma) >= this (Warn's cone, fig. 2.4)
  float dropoff = 0.0f;               // spot: Warn exponent P in cos(gamma)^P (eq. 5)
  float cos_inner_cone = 1.0f;        // smooth spot: full intensity where cos(gamma) >= this
  float range = std::numeric_limits<float>::infinity();  // dark where the distance exceeds it
  LightKind kind = LightKind::point;
  SpotProfile profile = SpotProfile::warn;
};

// Distances below this are clamped when evaluating 1/d^2: a shading point that sits on the light
// gets the (finite) irradiance of a point 1e-18 units away instead of Inf/NaN. Clamping only
// lowers irradiance, so every extent volume stays conservative. 1e-18 keeps d^2 (1e-36) a normal
// float, which the render threads' flush-to-zero leaves alone, and lies far below any distance in
// a scene within the scale limits (a 1e-6 clamp dimmed every light of a scene scaled by 1e-6
// that stood less than a unit, scaled, from a surface).
inline constexpr float kMinLightDistance = 1e-18f;

Light make_point_light(const glm::vec3& position, const glm::vec3& intensity);
// cone_half_angle_rad in [0, pi]; a cone of pi lights every direction. dropoff >= 0.
Light make_spot_light(const glm::vec3& position, const glm::vec3& direction,
                      const glm::vec3& intensity, float cone_half_angle_rad, float dropoff);
// A spot with the smooth profile (spot_profile.h): dark beyond outer_cone_rad, full inside
// inner_cone_rad; 0 <= inner < outer <= pi/2 as glTF requires.
Light make_smooth_spot_light(const glm::vec3& position, const glm::vec3& direction,
                             const glm::vec3& intensity, float inner_cone_rad,
                             float outer_cone_rad);

// The light seen through xf: moved, turned, and with intensity times scale^2 (the 1/d^2 law
// in the scaled frame), so irradiance(transform_light(l, xf), apply_point(xf, x)) equals
// irradiance(l, x).
// Inline, like irradiance_falloff: the walk and every shading loop call them once per light.
inline Light transform_light(const Light& light, const Similarity& xf) {
  Light l = light;
  l.position = apply_point(xf, light.position);
  l.intensity = light.intensity * (xf.scale * xf.scale);
  l.range = light.range * xf.scale;
  if (light.kind == LightKind::spot)
    l.direction = glm::normalize(apply_direction(xf, light.direction));
  return l;
}

// The brightest channel: the scale on which the per-light test, the culled bounds and the
// tolerance are compared (docs/design.md). The double one (a sum) is rounded to float.
inline float brightest(const glm::vec3& v) {
  return glm::max(glm::max(v.x, v.y), v.z);
}
inline float brightest(const glm::dvec3& v) {
  return static_cast<float>(glm::max(glm::max(v.x, v.y), v.z));
}

// Scalar strength used for culling: the brightest channel (docs/design.md).
inline float strength(const Light& light) {
  return brightest(light.intensity);
}

// The geometric factor of eq. 1/5: cos(gamma)^P / d^2 (spot) or 1 / d^2 (point), zero outside
// the cone and beyond the range. Multiply by intensity for the RGB irradiance.
inline float irradiance_falloff(const Light& light, const glm::vec3& x) {
  const glm::vec3 to_point = x - light.position;
  const float d2_raw = glm::dot(to_point, to_point);
  // An infinite range squares to infinity, so lights without one never take this branch.
  if (d2_raw > light.range * light.range) return 0.0f;
  const float d2 = std::max(d2_raw, kMinLightDistance * kMinLightDistance);
  if (light.kind == LightKind::point) return 1.0f / d2;
  // At the apex itself the direction is undefined; the point counts as on the axis.
  const float cos_gamma =
      d2_raw > 0.0f ? glm::dot(light.direction, to_point) / std::sqrt(d2_raw) : 1.0f;
  if (cos_gamma < light.cos_cone_half_angle) return 0.0f;
  if (light.profile == SpotProfile::smooth) {
    return smooth_spot_attenuation(cos_gamma, light.cos_cone_half_angle, light.cos_inner_cone) / d2;
  }
  if (light.dropoff == 0.0f) return 1.0f / d2;
  // Warn's cos^P is defined for the front hemisphere; behind the light (cone wider than 90
  // degrees) a spot with a dropoff contributes nothing. pow underflows to 0 for huge P, never NaN.
  if (cos_gamma <= 0.0f) return 0.0f;
  // P = 1 is common (glTF-like spots, the hall) and pow's call dominated the walk there;
  // pow(c, 1) is c exactly (checked for every float in (0, 1.0002]), so the result is the same.
  if (light.dropoff == 1.0f) return cos_gamma / d2;
  return std::pow(cos_gamma, light.dropoff) / d2;
}

// RGB irradiance, finite for every finite or infinite intensity: zero where the falloff is zero
// (no 0 * inf), and at most the largest float where 1/d^2 meets a huge intensity. The walk computes
// the falloff once for both this and the importance test below.
inline glm::vec3 irradiance_from_falloff(const Light& light, float falloff) {
  if (falloff == 0.0f) return glm::vec3(0.0f);
  constexpr float kLargest = std::numeric_limits<float>::max();
  const glm::vec3 e = light.intensity * falloff;
  return {e.x < kLargest ? e.x : kLargest, e.y < kLargest ? e.y : kLargest,
          e.z < kLargest ? e.z : kLargest};
}
inline glm::vec3 irradiance(const Light& light, const glm::vec3& x) {
  return irradiance_from_falloff(light, irradiance_falloff(light, x));
}

// True when the light's unshadowed irradiance at x is non-zero and at least tolerance: the
// exact extent volume of one light (thesis 3.3). With tolerance 0 it selects every light that
// can contribute at all, which is what `rt` shadow-tests.
inline bool is_important_from_falloff(const Light& light, float falloff, float tolerance) {
  // Clamped like irradiance(), so an infinite tolerance culls every light.
  const float e = std::min(strength(light) * falloff, std::numeric_limits<float>::max());
  return e > 0.0f && e >= tolerance;
}
inline bool is_important(const Light& light, const glm::vec3& x, float tolerance) {
  return is_important_from_falloff(light, irradiance_falloff(light, x), tolerance);
}

}  // namespace lev
