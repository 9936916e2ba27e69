// Unit vectors that survive the render threads' float mode. Rays are cast with flush-to-zero and
// denormals-are-zero (denormal_mode.h), so glm::normalize of a vector shorter than about 1e-19
// squares to zero and returns NaN, and one longer than about 1e19 squares to +inf and returns
// zero. robust_normalize scales such a vector by its largest component first; a ray whose
// direction is still not castable (zero or not finite) is never handed to Embree.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace renderer {

// glm::normalize itself whenever |v|^2 is a normal float (so images of ordinary scenes keep
// every bit); otherwise v divided by its largest component magnitude, then normalised. Zero when
// v is zero (or denormal, which the render mode reads as zero) or not finite.
inline glm::vec3 robust_normalize(const glm::vec3& v) {
  const float length_squared = glm::dot(v, v);
  if (length_squared >= std::numeric_limits<float>::min() &&
      length_squared <= std::numeric_limits<float>::max()) {
    return glm::normalize(v);
  }
  const glm::vec3 a = glm::abs(v);
  const float largest = std::max(std::max(a.x, a.y), a.z);
  if (!(largest > 0.0f) || !std::isfinite(largest)) return glm::vec3(0.0f);
  return glm::normalize(v / largest);
}

// What Embree needs of a ray: a finite origin and a finite, non-zero direction.
inline bool castable(const glm::vec3& origin, const glm::vec3& direction) {
  const bool finite = std::isfinite(origin.x) && std::isfinite(origin.y) &&
                      std::isfinite(origin.z) && std::isfinite(direction.x) &&
                      std::isfinite(direction.y) && std::isfinite(direction.z);
  return finite && direction != glm::vec3(0.0f);
}

}  // namespace renderer
