// What the error-bound tests share (renderer/error_bound.h): a selector that reports no direct
// light and a culled irradiance bound of 1 in every channel, so the error bound a trace carries
// with it is the sum over the path's shading points of the path weight times the material's
// largest response (the measure any selector's bound is compared with); and the mirror and glass
// whose bound comes mostly through kr and kt.
#pragma once

#include <glm/glm.hpp>

#include "lev/light_selector.h"
#include "renderer/material.h"

namespace levrt_test {

class UnitCulledSelector final : public lev::LightSelector {
 public:
  glm::vec3 direct_radiance(lev::ShadingPoint&, lev::SelectorScratch&, lev::SelectionCounters&,
                            glm::vec3* culled_irradiance_bound = nullptr) const override {
    if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(1.0f);
    return glm::vec3(0.0f);
  }
};

// A pure mirror: its own bound is 0, all of it comes through kr.
inline renderer::Material pure_mirror() {
  renderer::Material m;
  m.kd = 0.0f;
  m.kr = 0.9f;
  return m;
}

// Mostly transmitting glass with a glint and a faint reflection.
inline renderer::Material clear_glass() {
  renderer::Material m;
  m.kd = 0.05f;
  m.ks = 0.3f;
  m.kr = 0.1f;
  m.kt = 0.85f;
  return m;
}

}  // namespace levrt_test
