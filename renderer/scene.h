// A renderable scene as scenes/ builds it: camera, light hierarchy (its description and the
// flattened structure), geometry and materials.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lev/light_description.h"
#include "lev/light_hierarchy.h"
#include "renderer/camera.h"
#include "renderer/directional_light.h"
#include "renderer/geometry.h"
#include "renderer/material.h"
#include "renderer/texture.h"

namespace renderer {

struct Scene {
  std::string name;
  int level = 0;  // model level (0 for scenes without one)
  Camera camera;
  lev::LightDescription light_description;
  lev::LightHierarchy lights;
  std::vector<DirectionalLight> directional_lights;
  Geometry geometry;
  std::vector<Material> materials;
  std::vector<Texture> textures;  // what materials' colour_texture indexes
  glm::vec3 ambient{1.0f};        // I_a of eq. 3
  glm::vec3 background{0.0f};     // radiance of rays that leave the scene
  // Everything above is in render space: world = render space + world_origin. Far-away scenes
  // are moved near the origin to keep float precision (scenes/scene_instantiation.h).
  glm::vec3 world_origin{0.0f};
};

}  // namespace renderer
