// glTF 2.0 scenes (.gltf, .glb) read through Debian's tinygltf into the same scene description
// the JSON scene files give (scene_description.h), so everything downstream is unchanged.
// What is imported: the node tree of the default scene (TRS or matrix), KHR_lights_punctual point
// and spot lights at their node's world position shining along its world -Z (a glTF light is
// never scaled by its node, as the extension says), the first perspective camera or else a view
// framing the lights. Not imported: triangle meshes, directional lights, a spot's falloff from its
// inner cone (the cone is hard at outerConeAngle) and `range`; the first of each is named in one
// warning line on stderr, printed only once the file is accepted. Every problem in the file
// becomes one line "FILE: what: value" in a std::invalid_argument.
#pragma once

#include <string>
#include <string_view>

#include "scenes/scene_description.h"

namespace scenes {

// glTF light intensity is in candela (lm/sr), which is already irradiance at distance 1 in
// levrt's units; one factor maps the physical scale of the sample assets to the display range.
inline constexpr float kDefaultGltfLightScale = 1.0f;
inline constexpr std::size_t kMaxGltfNodes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxGltfAccessorElements = std::size_t{1} << 25;

// True for names ending in ".gltf" or ".glb".
bool is_gltf_file_name(std::string_view name);

// `bytes` is the whole file, `path` names it in messages and locates external buffers.
SceneDescription parse_gltf_scene(const std::string& bytes, const std::string& path,
                                  float light_scale = kDefaultGltfLightScale);

}  // namespace scenes
