// Phong materials with Whitted's reflection and transmission coefficients (thesis eq. 7).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace renderer {

struct Material {
  glm::vec3 colour{0.8f};   // tints the ambient and diffuse terms
  float ka = 0.1f;          // ambient coefficient
  float kd = 0.7f;          // diffuse coefficient
  float ks = 0.0f;          // specular coefficient
  float shininess = 20.0f;  // Phong exponent n
  float kr = 0.0f;          // mirror reflection
  float kt = 0.0f;          // transmission
  float ior = 1.5f;         // index of refraction for transmission
  // Index into Scene::textures whose colour at the hit's uv multiplies `colour`, or -1.
  std::int32_t colour_texture = -1;
};

}  // namespace renderer
