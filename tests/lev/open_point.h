// A shading point for selector tests: a surface that faces every light, reflects irradiance
// unchanged and is never shadowed, so the direct radiance is the sum of the irradiance of the
// lights a method accounts for.
#pragma once

#include "lev/light.h"
#include "lev/light_selector.h"

namespace lev_test {

class OpenPoint final : public lev::ShadingPoint {
 public:
  explicit OpenPoint(const glm::vec3& x) : x_(x) {}
  glm::vec3 position() const override { return x_; }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    return lev::irradiance(light, x_);
  }
  bool visible(const lev::Light&) override { return true; }

 private:
  glm::vec3 x_;
};

}  // namespace lev_test
