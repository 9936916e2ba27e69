#include "lev/light.h"

#include <algorithm>
#include <cmath>

namespace lev {

Light make_point_light(const glm::vec3& position, const glm::vec3& intensity) {
  Light l;
  l.position = position;
  l.intensity = intensity;
  return l;
}

Light make_spot_light(const glm::vec3& position, const glm::vec3& direction,
                      const glm::vec3& intensity, float cone_half_angle_rad, float dropoff) {
  Light l;
  l.kind = LightKind::spot;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.intensity = intensity;
  l.cos_cone_half_angle = static_cast<float>(std::cos(std::clamp<double>(cone_half_angle_rad, 0.0, M_PI)));
  l.dropoff = dropoff;
  return l;
}

Light transform_light(const Light& light, const Similarity& xf) {
  Light l = light;
  l.position = apply_point(xf, light.position);
  l.intensity = light.intensity * (xf.scale * xf.scale);
  if (light.kind == LightKind::spot) l.direction = glm::normalize(apply_direction(xf, light.direction));
  return l;
}

float irradiance_falloff(const Light& light, const glm::vec3& x) {
  const glm::vec3 to_point = x - light.position;
  const float d2_raw = glm::dot(to_point, to_point);
  const float d2 = std::max(d2_raw, kMinLightDistance * kMinLightDistance);
  if (light.kind == LightKind::point) return 1.0f / d2;
  // At the apex itself the direction is undefined; the point counts as on the axis.
  const float cos_gamma = d2_raw > 0.0f ? glm::dot(light.direction, to_point) / std::sqrt(d2_raw) : 1.0f;
  if (cos_gamma < light.cos_cone_half_angle) return 0.0f;
  if (light.dropoff == 0.0f) return 1.0f / d2;
  // Warn's cos^P is defined for the front hemisphere; behind the light (cone wider than 90
  // degrees) a spot with a dropoff contributes nothing. pow underflows to 0 for huge P, never NaN.
  if (cos_gamma <= 0.0f) return 0.0f;
  return std::pow(cos_gamma, light.dropoff) / d2;
}

}  // namespace lev
