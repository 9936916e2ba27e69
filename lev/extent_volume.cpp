#include "lev/extent_volume.h"

#include <algorithm>
#include <cmath>

namespace lev {

float extent_radius(float light_strength, float tolerance) {
  if (!(light_strength > 0.0f)) return 0.0f;
  if (tolerance <= 0.0f) return std::numeric_limits<float>::infinity();
  const double r = std::sqrt(static_cast<double>(light_strength) / static_cast<double>(tolerance));
  return r >= static_cast<double>(std::numeric_limits<float>::max())
             ? std::numeric_limits<float>::infinity()
             : static_cast<float>(r);
}

Bounds light_extent_bounds(const Light& light, float tolerance) {
  const float r = extent_radius(strength(light), tolerance);
  if (r == 0.0f) return Bounds{};
  if (std::isinf(r)) return infinite_bounds();
  const glm::vec3 p = light.position;
  if (light.kind == LightKind::point || light.cos_cone_half_angle <= 0.0f) {
    return {p - glm::vec3(r), p + glm::vec3(r)};
  }
  // Cone of half-angle delta around axis a, cut by the sphere: along axis e_i the farthest reach
  // is r * cos(angle(e_i, a) - delta) when that angle exceeds delta, r when the cone contains e_i,
  // and the apex (0) when the cone points away.
  const double delta = std::acos(std::clamp<double>(light.cos_cone_half_angle, -1.0, 1.0));
  Bounds b;
  for (int i = 0; i < 3; ++i) {
    const double a_i = std::clamp<double>(light.direction[i], -1.0, 1.0);
    const double reach_pos = std::max(0.0, std::cos(std::max(0.0, std::acos(a_i) - delta)));
    const double reach_neg = std::max(0.0, std::cos(std::max(0.0, std::acos(-a_i) - delta)));
    b.hi[i] = p[i] + static_cast<float>(r * reach_pos);
    b.lo[i] = p[i] - static_cast<float>(r * reach_neg);
  }
  return b;
}

}  // namespace lev
