#include "renderer/camera.h"

#include <cmath>

namespace renderer {

Ray primary_ray(const Camera& camera, int width, int height, float image_x, float image_y) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 up = glm::cross(right, forward);
  const float half_h = std::tan(glm::radians(camera.vertical_fov_deg) * 0.5f);
  const float half_w = half_h * static_cast<float>(width) / static_cast<float>(height);
  const float sx = (2.0f * image_x / static_cast<float>(width) - 1.0f) * half_w;
  const float sy = (1.0f - 2.0f * image_y / static_cast<float>(height)) * half_h;
  return {camera.position, glm::normalize(forward + sx * right + sy * up)};
}

}  // namespace renderer
