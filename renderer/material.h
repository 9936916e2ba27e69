// Phong materials with Whitted's reflection and transmission coefficients (thesis eq. 7), and
// what glTF materials add: emission, unlit surfaces, single-sided surfaces and alpha cut-outs.
// The defaults (every built-in scene and scene file) are a two-sided, opaque, lit surface that
// emits nothing, which the shading and Embree's traversal take without any extra work.
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
  // Radiance the surface emits toward every ray that hits it (camera, reflected or refracted
  // ones), times the texture at the hit's uv when emission_texture >= 0. It lights nothing else:
  // emission is not a light source for shadow rays or the light tree.
  glm::vec3 emission{0.0f};
  std::int32_t emission_texture = -1;
  // The colour (texture included) is the radiance, as is: no lighting, reflection or refraction.
  bool unlit = false;
  // Camera rays do not see the side against the triangles' winding (a glTF single-sided
  // material); reflected, refracted and shadow rays meet both sides (ray_scene.h).
  bool cull_back_faces = false;
  // A cut-out (glTF alphaMode MASK) when alpha_cutoff >= 0: where alpha_factor times the alpha
  // texture (its texels hold the alpha in every channel) at the hit's uv is below alpha_cutoff,
  // every ray passes through the surface.
  float alpha_cutoff = -1.0f;
  float alpha_factor = 1.0f;
  std::int32_t alpha_texture = -1;
  bool has_emission() const { return emission != glm::vec3(0.0f); }
  bool is_cut_out() const { return alpha_cutoff >= 0.0f; }
};

}  // namespace renderer
