// Mouse camera moves for the viewer, as pure functions of a pinhole camera: orbit around the
// target (yaw about the camera's up axis, pitch kept away from the poles), pan of target and eye
// together in the image plane, and zoom toward the target. No move takes the camera past the
// bound the camera flags have (a coordinate or orthographic half height of 1e6): a move that
// would is not made, and a zoom out stops at it.
#pragma once

#include "renderer/camera.h"

namespace app::viewer {

// Whether the camera's position, target and orthographic half height are within that bound.
bool camera_within_bounds(const renderer::Camera& camera);

// Angles in radians; positive yaw turns the eye counter-clockwise about `up` seen from above,
// positive pitch raises the eye.
renderer::Camera orbit_camera(const renderer::Camera& camera, float yaw, float pitch);

// Moves eye and target by (right, up) in units of the visible image height at the target, so a
// drag across the whole image height moves the scene by exactly that much.
renderer::Camera pan_camera(const renderer::Camera& camera, float right, float up);

// Multiplies the eye-target distance by `factor` (< 1 moves closer), keeping a small minimum.
renderer::Camera zoom_camera(const renderer::Camera& camera, float factor);

}  // namespace app::viewer
