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
  l.cos_cone_half_angle =
      static_cast<float>(std::cos(std::clamp<double>(cone_half_angle_rad, 0.0, M_PI)));
  l.dropoff = dropoff;
  return l;
}

Light make_smooth_spot_light(const glm::vec3& position, const glm::vec3& direction,
                             const glm::vec3& intensity, float inner_cone_rad,
                             float outer_cone_rad) {
  Light l = make_spot_light(position, direction, intensity, outer_cone_rad, 0.0f);
  l.profile = SpotProfile::smooth;
  l.cos_inner_cone = static_cast<float>(std::cos(std::clamp<double>(inner_cone_rad, 0.0, M_PI)));
  return l;
}

}  // namespace lev
