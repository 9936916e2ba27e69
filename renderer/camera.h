// A pinhole camera, or an orthographic one (glTF's orthographic cameras), and the primary ray
// through a point of the image plane.
#pragma once

#include <glm/glm.hpp>

namespace renderer {

struct Camera {
  glm::vec3 position{0.0f, -10.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float vertical_fov_deg = 45.0f;
  // Above 0: an orthographic camera seeing this half height (scene units) around the view axis,
  // every ray parallel to it and starting on the camera's plane; the field of view is then
  // unused. 0: perspective.
  float orthographic_half_height = 0.0f;
  bool orthographic() const { return orthographic_half_height > 0.0f; }
};

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit
};

// The camera's orthonormal frame as the render threads compute it (direction.h): forward, right
// and up are zero when the target equals the position or up is zero or parallel to the view, in
// the float mode of the caller. Scene validation calls it in the render mode to refuse such
// cameras.
struct CameraBasis {
  glm::vec3 forward{0.0f}, right{0.0f}, up{0.0f};
};
CameraBasis camera_basis(const Camera& camera);

// (image_x, image_y) in pixels from the top-left corner, fractional (0.5 = pixel centre).
// The direction is zero (the ray is not cast) when the camera has no basis.
Ray primary_ray(const Camera& camera, int width, int height, float image_x, float image_y);

// The inverse: where a world point appears on the image, in pixels from the top-left corner
// (fractional, possibly outside the image), and its depth along the view direction; false for a
// point at or behind the camera plane, or a camera without a basis.
bool project_point(const Camera& camera, int width, int height, const glm::vec3& world,
                   glm::vec2& image, float& depth);

}  // namespace renderer
