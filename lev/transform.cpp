#include "lev/transform.h"

#include <cmath>

namespace lev {

Similarity make_translation(const glm::vec3& t) {
  Similarity xf;
  xf.translation = t;
  return xf;
}

Similarity make_rotation(const glm::vec3& axis, float angle_rad) {
  const glm::vec3 a = glm::normalize(axis);
  const float c = std::cos(angle_rad), s = std::sin(angle_rad), t = 1.0f - c;
  Similarity xf;
  // Rodrigues' formula, column-major: rotation[col][row].
  xf.rotation[0] = {t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y};
  xf.rotation[1] = {t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x};
  xf.rotation[2] = {t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c};
  return xf;
}

Similarity make_scale(float s) {
  Similarity xf;
  xf.scale = s;
  return xf;
}

}  // namespace lev
