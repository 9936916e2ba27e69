// Where a scene is traced: near the origin, whatever its coordinates.
#pragma once

#include <glm/glm.hpp>

#include "renderer/camera.h"
#include "scenes/scene_description.h"

namespace scenes {

// Render space. Floats near 1e6 are 0.0625 apart, and ray offsets grow with the coordinates, so a
// scene traced where it stands near 1e6 gets coarse hit points and shadow rays that start past
// the occluders (light leaks) or inside the surface (acne). A far scene is therefore
// instantiated moved by -origin, origin being the camera position rounded to whole units:
// geometry, lights, light hierarchy and camera alike, so every ray, hit and hierarchy query is
// computed near the origin. Moving is a subtraction of floats of like magnitude (exact).
// Far means: the camera is at least kRenderSpaceRebaseDistance from the world origin and more
// than kRenderSpaceRebaseRatio times farther from it than from its target (the size of what is
// in view). Moving gains little otherwise, and an instance moved gets a transform node of its
// own; so nearer scenes, and scenes that merely extend far from the origin such as the largest
// buildings, stay where they are (origin 0) and render exactly as before.
// renderer::Scene::world_origin records the origin.
inline constexpr float kRenderSpaceRebaseDistance = 4096.0f;
inline constexpr float kRenderSpaceRebaseRatio = 16.0f;
glm::vec3 render_space_origin(const renderer::Camera& camera);

// Moves a subtree by `offset`, as if a translation sat right above it, without adding a level
// where the subtree has coordinates of its own: an affine node takes the offset into its
// translation (one subtraction, exact for floats of like magnitude), shapes shift their points,
// a union passes it to each child. Lights and instances have no coordinates of their own (a
// master is shared, so it cannot be moved) and get a translate node. Depth is bounded by
// kMaxNodeDepth, checked before.
void move_subtree(SceneNode& node, const glm::vec3& offset);

}  // namespace scenes
