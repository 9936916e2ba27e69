// glTF's KHR_lights_punctual read for the importer (gltf_scene.h): the file's light list checked
// (intensity, range, colour, cone angles, type), the light a node carries, and a point or spot
// light placed at a node made into levrt's scene node (its -Z turned onto the light's direction).
#pragma once

#include <string>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "scenes/scene_description.h"

namespace scenes {

// Every light of the file is one levrt can render; else a refusal naming it (`path`: the file).
void check_gltf_lights(const tinygltf::Model& model, const std::string& path);

// The index of the light node `node` carries (at glTF path `where`), or -1 for none.
int gltf_light_of(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& path,
                  const std::string& where);

// A point or spot light (checked by check_gltf_lights) of `intensity` at `position`, shining
// along the unit `direction`.
SceneNode gltf_light_node(const tinygltf::Light& light, const glm::vec3& intensity,
                          const glm::dvec3& position, const glm::dvec3& direction);

}  // namespace scenes
