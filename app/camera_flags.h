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
#include "scenes/scene_choice.h"

namespace app {

// The flags' values (the scene choice's, scenes/scene_choice.h).
using CameraFlags = scenes::CameraFlags;

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
// The preset is in render space (scenes/render_space.h: world = render space + world_origin); the
// flags' position and target are in the scene's own (world) coordinates, as a user reads them
// from the scene file and from stats, so they are moved by -world_origin.
renderer::Camera apply_camera_flags(const renderer::Camera& preset, const CameraFlags& flags,
                                    const glm::vec3& world_origin);

// A render-space camera in the scene's own coordinates (position and target + world_origin):
// what the stats report and Copy camera gives, so that the flags made from them, applied by
// apply_camera_flags, give the same view.
renderer::Camera world_camera(const renderer::Camera& render_space, const glm::vec3& world_origin);

// The camera as the four flags, in shortest round-trip notation (parsing them gives the same
// floats): "--camera-position X,Y,Z --camera-target X,Y,Z --camera-up X,Y,Z --fov DEG", with
// "--ortho-half-height H" in place of --fov for an orthographic camera.
std::string camera_flags_text(const renderer::Camera& camera);

}  // namespace app
