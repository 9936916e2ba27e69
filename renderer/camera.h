// A pinhole camera and the primary ray through a point of the image plane.
#pragma once

#include <glm/glm.hpp>

namespace renderer {

struct Camera {
  glm::vec3 position{0.0f, -10.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float vertical_fov_deg = 45.0f;
};

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit
};

// (image_x, image_y) in pixels from the top-left corner, fractional (0.5 = pixel centre).
Ray primary_ray(const Camera& camera, int width, int height, float image_x, float image_y);

}  // namespace renderer
