#include "lev/bounds.h"

#include <cmath>

namespace lev {

Bounds infinite_bounds() {
  const float inf = std::numeric_limits<float>::infinity();
  return {glm::vec3(-inf), glm::vec3(inf)};
}

bool is_finite(const Bounds& b) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i])) return false;
  }
  return true;
}

Bounds transform_bounds(const Bounds& b, const Similarity& xf) {
  if (is_empty(b)) return b;
  if (!is_finite(b)) return infinite_bounds();
  Bounds r;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                      (corner & 4) ? b.hi.z : b.lo.z};
    const glm::vec3 q = apply_point(xf, p);
    r.lo = glm::min(r.lo, q);
    r.hi = glm::max(r.hi, q);
  }
  if (!is_finite(r)) return infinite_bounds();
  return r;
}

float round_outwards(double x, int direction) {
  auto f = static_cast<float>(x);
  if (direction > 0 && static_cast<double>(f) < x)
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  if (direction < 0 && static_cast<double>(f) > x)
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

Bounds pad_bounds(const Bounds& b, float relative) {
  if (is_empty(b) || !is_finite(b)) return b;
  const glm::vec3 extent = b.hi - b.lo;
  const glm::vec3 magnitude = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  const float margin = relative * (glm::max(glm::max(extent.x, extent.y), extent.z) +
                                   glm::max(glm::max(magnitude.x, magnitude.y), magnitude.z)) +
                       std::numeric_limits<float>::min();
  return {b.lo - margin, b.hi + margin};
}

}  // namespace lev
