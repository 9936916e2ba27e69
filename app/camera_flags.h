// The camera flags every rendering command takes: --camera-position, --camera-target and
// --camera-up (X,Y,Z each), --fov (vertical, degrees) and --camera-from (a stats JSON whose
// "camera" object levrt wrote). Each flag replaces one part of the scene's preset camera, so
// `--fov 30` alone narrows the preset view; --camera-from gives all four and the other flags
// still override it. --ortho-half-height H makes the view orthographic (H scene units above and
// below its axis, as a glTF orthographic camera's ymag), --fov makes it perspective; not both.
// The viewer's "Copy camera" writes the current view as these flags.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "renderer/camera.h"

namespace app {

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
  bool operator==(const CameraFlags& o) const {
    return position == o.position && target == o.target && up == o.up &&
           vertical_fov_deg == o.vertical_fov_deg &&
           orthographic_half_height == o.orthographic_half_height && from_file == o.from_file;
  }
  bool operator!=(const CameraFlags& o) const { return !(*this == o); }
};

// The flags as typed; an empty text is a flag not given.
struct CameraFlagTexts {
  std::string position, target, up, fov_deg, ortho_half_height, from_file;
};

// A stats file read by --camera-from is refused above this size before it is read.
inline constexpr std::uintmax_t kMaxCameraFileBytes = std::uintmax_t{1} << 20;

// Parses the flags (--camera-from first, then the others over it); throws UsageError naming the
// flag and the value ("--camera-position: must be X,Y,Z (three finite numbers), got '1,2'").
CameraFlags parse_camera_flags(const CameraFlagTexts& texts);

// The preset with the flags' parts replaced; throws UsageError when the result cannot look
// anywhere (target at the position, up along the view) or the field of view is outside (0, 180).
renderer::Camera apply_camera_flags(const renderer::Camera& preset, const CameraFlags& flags);

// The camera as the four flags, in shortest round-trip notation (parsing them gives the same
// floats): "--camera-position X,Y,Z --camera-target X,Y,Z --camera-up X,Y,Z --fov DEG", with
// "--ortho-half-height H" in place of --fov for an orthographic camera.
std::string camera_flags_text(const renderer::Camera& camera);

}  // namespace app
