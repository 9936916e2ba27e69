// Similarity transforms (rotation, uniform scale, translation): the affine nodes of the light
// hierarchy and the placement of geometry instances. Only similarities are allowed so that a
// sphere stays a sphere, a cone keeps its angle, and the light's 1/d^2 law maps exactly: a light
// scaled by s shines with s^2 its intensity (thesis 4.2.2: "by using a scale transformation, a
// light source can be defined with any light intensity value").
#pragma once

#include <glm/glm.hpp>

namespace lev {

struct Similarity {
  glm::mat3 rotation{1.0f};  // orthonormal
  float scale = 1.0f;        // uniform, > 0
  glm::vec3 translation{0.0f};
};

inline glm::vec3 apply_point(const Similarity& xf, const glm::vec3& p) {
  return xf.rotation * (xf.scale * p) + xf.translation;
}
inline glm::vec3 apply_direction(const Similarity& xf, const glm::vec3& d) {
  return xf.rotation * d;
}
inline glm::vec3 apply_inverse_point(const Similarity& xf, const glm::vec3& p) {
  return (glm::transpose(xf.rotation) * (p - xf.translation)) / xf.scale;
}
// outer(inner(x)): the frame of a child seen from its parent's parent.
inline Similarity compose(const Similarity& outer, const Similarity& inner) {
  Similarity r;
  r.rotation = outer.rotation * inner.rotation;
  r.scale = outer.scale * inner.scale;
  r.translation = apply_point(outer, inner.translation);
  return r;
}
inline bool is_identity(const Similarity& xf) {
  return xf.rotation == glm::mat3(1.0f) && xf.scale == 1.0f && xf.translation == glm::vec3(0.0f);
}

Similarity make_translation(const glm::vec3& t);
// Rotation by angle_rad about a non-zero axis (right-handed).
Similarity make_rotation(const glm::vec3& axis, float angle_rad);
Similarity make_scale(float s);

}  // namespace lev
