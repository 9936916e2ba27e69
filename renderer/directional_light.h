// A light at infinity (a glTF directional light, a sun): the same irradiance everywhere,
// arriving against `direction`. It has no extent volume (its irradiance never falls below any
// tolerance), so it lives outside the light hierarchy and every method shadow-tests it at every
// shading point with a ray to infinity; lev at tolerance 0 therefore still equals rt.
#pragma once

#include <glm/glm.hpp>

namespace renderer {

struct DirectionalLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit, the way the light travels
  glm::vec3 irradiance{1.0f};              // RGB, on a surface facing the light
};

}  // namespace renderer
