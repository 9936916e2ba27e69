// The scene the user asks for: the scenes layer's group of the user's settings (app/settings.h
// composes it; app/scene_loading.h loads it). Two choices compare equal when they load the same
// scene seen from the same preset camera: the camera index, which only a glTF file reads, is not
// compared for any other scene, so changing it there restarts nothing.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scenes/scene_models.h"

namespace scenes {

// --camera-position/-target/-up, --fov, --ortho-half-height and --camera-from
// (app/camera_flags.h parses them): the parts of the preset camera replaced.
struct CameraFlags {
  std::optional<glm::vec3> position;
  std::optional<glm::vec3> target;
  std::optional<glm::vec3> up;
  std::optional<float> vertical_fov_deg;
  std::optional<float> orthographic_half_height;  // 0: perspective
  std::string from_file;  // --camera-from's file (an input: no output may replace it)
  bool empty() const {
    return !position && !target && !up && !vertical_fov_deg && !orthographic_half_height;
  }
};
bool operator==(const CameraFlags& a, const CameraFlags& b);
bool operator!=(const CameraFlags& a, const CameraFlags& b);

struct SceneChoice {
  std::string name = "building";   // a model (scene_models.h), or a .json/.gltf/.glb file
  int level = kDefaultSceneLevel;  // model level; --lights picks it by light count instead
  int camera = 0;                  // a glTF file's camera, in node order
  // They belong to the scene they were given with: the viewer drops them when another opens.
  CameraFlags camera_flags;
};
bool operator==(const SceneChoice& a, const SceneChoice& b);
bool operator!=(const SceneChoice& a, const SceneChoice& b);

// Whether the scene reads the camera index (a glTF file's cameras; other scenes have one preset).
bool reads_camera_index(const SceneChoice& choice);

}  // namespace scenes
