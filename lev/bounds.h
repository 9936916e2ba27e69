// Axis-aligned boxes: the extent volumes stored in the hierarchy. A box may be infinite (tolerance
// 0 makes every extent unbounded); every operation here keeps infinities meaningful (no NaN).
#pragma once

#include <limits>

#include <glm/glm.hpp>

#include "lev/transform.h"

namespace lev {

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
};

inline bool is_empty(const Bounds& b) {
  return b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z;
}
// Branch-free: the walk's outcome per box is unpredictable, so one branch on the result is
// cheaper than six short-circuit ones.
inline bool contains(const Bounds& b, const glm::vec3& p) {
  return (p.x >= b.lo.x) & (p.x <= b.hi.x) & (p.y >= b.lo.y) & (p.y <= b.hi.y) & (p.z >= b.lo.z) &
         (p.z <= b.hi.z);
}
inline Bounds merge(const Bounds& a, const Bounds& b) {
  return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}
Bounds infinite_bounds();
bool is_finite(const Bounds& b);
// The box around the transformed box (its 8 corners). An infinite box stays infinite.
Bounds transform_bounds(const Bounds& b, const Similarity& xf);
// The float at or beyond x in the given direction (+1: up, -1: down), so that a bound computed
// in double never moves inwards when stored.
float round_outwards(double x, int direction);
// Grows the box by a relative margin so that float rounding in the walk (which moves the query
// point through the inverse transforms) can never cull a light whose world irradiance passes.
Bounds pad_bounds(const Bounds& b, float relative);

}  // namespace lev
