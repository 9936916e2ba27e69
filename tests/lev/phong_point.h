// A shading point for selector and bound tests with a real surface: shading.cpp's Phong response
// (thesis eq. 6) and surface_response, its shadow rays blocked for a fixed pseudo-random half of
// the light positions.
#pragma once

#include <cmath>
#include <functional>

#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_selector.h"

namespace lev_test {

class PhongPoint final : public lev::ShadingPoint {
 public:
  PhongPoint(const glm::vec3& x, const glm::vec3& normal, const glm::vec3& to_viewer,
             const glm::vec3& diffuse, float specular, float shininess)
      : x_(x), normal_(normal), to_viewer_(to_viewer) {
    surface_.normal = normal;
    surface_.mirrored_view = 2.0f * glm::dot(normal, to_viewer) * normal - to_viewer;
    surface_.diffuse = diffuse;
    surface_.specular = specular;
    surface_.shininess = shininess;
  }
  glm::vec3 position() const override { return x_; }
  glm::vec3 normal() const override { return normal_; }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    const glm::vec3 to_light = light.position - x_;
    const float d2 = glm::dot(to_light, to_light);
    if (!(d2 > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 l = to_light / std::sqrt(d2);
    const float cos_theta = glm::dot(normal_, l);
    if (cos_theta <= 0.0f) return glm::vec3(0.0f);
    glm::vec3 r = surface_.diffuse * cos_theta;
    if (surface_.specular > 0.0f) {
      const float cos_alpha = glm::dot(2.0f * cos_theta * normal_ - l, to_viewer_);
      if (cos_alpha > 0.0f)
        r += glm::vec3(surface_.specular * std::pow(cos_alpha, surface_.shininess));
    }
    return lev::irradiance(light, x_) * r;
  }
  bool visible(const lev::Light& light) override {
    return (std::hash<float>()(light.position.x + 3.0f * light.position.y) & 1u) == 0;
  }
  lev::SurfaceResponse surface_response() const override { return surface_; }

 private:
  glm::vec3 x_, normal_, to_viewer_;
  lev::SurfaceResponse surface_;
};

}  // namespace lev_test
