// glTF 2.0 scenes (.gltf, .glb) read through Debian's tinygltf into the same scene description
// the JSON scene files give (scene_description.h), so everything downstream is unchanged.
// What is imported: the node tree of the default scene (TRS or matrix); triangle meshes (each
// glTF mesh once, placed by every node that draws it) with their materials (gltf_materials.h:
// pbrMetallicRoughness mapped onto Phong, emission, unlit, single sides, cut-outs);
// KHR_lights_punctual point and spot lights at their node's world position shining along its
// world -Z (a glTF light is never scaled by its node, as the extension says) with their range
// and the smooth falloff between the inner and outer cone; directional lights as suns outside
// the hierarchy; the chosen camera (perspective, or orthographic with ymag as its half height),
// or else a view framing the scene from the front and above. Points and lines are skipped with
// one warning line naming the mesh, and what materials carry that levrt does not render with one
// line per kind, printed only once the file is accepted. Every problem in the file
// becomes one line "FILE: glTF.path: value" in a std::invalid_argument. Before tinygltf sees
// the text, gltf_document.h checks its JSON (nesting, indices, URIs inside the file's folder);
// before anything is built, gltf_budget.h charges the whole scene's memory. The node tree is
// walked with an explicit stack, so its depth is bounded only by kMaxGltfNodes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "scenes/gltf_budget.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr std::size_t kMaxGltfNodes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxGltfAccessorElements = std::size_t{1} << 25;

// True for names ending in ".gltf" or ".glb".
bool is_gltf_file_name(std::string_view name);

// `bytes` is the whole file, `path` names it in messages and locates external buffers. camera:
// the index of the camera to look through among those the scene's nodes carry (depth
// first); 0 falls back to the framing view when there is none, any other index must exist.
// Light intensities are used as authored (candela for point and spot lights, lux for
// directional ones, as irradiance at distance 1): photometric, usually far above levrt's 1.0 =
// 255, and brought to the display by the exposure (glTF files open at --exposure auto).
// budget_bytes caps the scene's memory as gltf_budget.h charges it; the glTF fuzz target passes a
// few MiB so that scenes near the cap stay fast under the sanitizers.
SceneDescription parse_gltf_scene(const std::string& bytes, const std::string& path, int camera = 0,
                                  std::uint64_t budget_bytes = kMaxGltfSceneBytes);

}  // namespace scenes
