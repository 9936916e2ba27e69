#include "scenes/scene_choice.h"

#include "scenes/gltf_scene.h"

namespace scenes {

bool operator==(const CameraFlags& a, const CameraFlags& b) {
  // Binding every member: a member added to CameraFlags stops this compiling until it is
  // compared too.
  const auto& [position, target, up, vertical_fov_deg, orthographic_half_height, from_file] = a;
  return position == b.position && target == b.target && up == b.up &&
         vertical_fov_deg == b.vertical_fov_deg &&
         orthographic_half_height == b.orthographic_half_height && from_file == b.from_file;
}

bool operator!=(const CameraFlags& a, const CameraFlags& b) {
  return !(a == b);
}

bool reads_camera_index(const SceneChoice& choice) {
  return is_gltf_file_name(choice.name);
}

bool operator==(const SceneChoice& a, const SceneChoice& b) {
  // Binding every member: a member added to SceneChoice stops this compiling until it is
  // compared too.
  const auto& [name, level, camera, camera_flags] = a;
  const bool same_camera = camera == b.camera || !reads_camera_index(a);
  return name == b.name && level == b.level && same_camera && camera_flags == b.camera_flags;
}

bool operator!=(const SceneChoice& a, const SceneChoice& b) {
  return !(a == b);
}

}  // namespace scenes
