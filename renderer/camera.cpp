#include "renderer/camera.h"

#include <cmath>

#include "renderer/direction.h"

namespace renderer {
namespace {

// The image's half height on the plane at distance 1 (perspective) or at any distance
// (orthographic).
float half_height_at_unit_depth(const Camera& camera) {
  if (camera.orthographic()) return camera.orthographic_half_height;
  return std::tan(glm::radians(camera.vertical_fov_deg) * 0.5f);
}

}  // namespace

CameraBasis camera_basis(const Camera& camera) {
  CameraBasis basis;
  basis.forward = robust_normalize(camera.target - camera.position);
  basis.right = robust_normalize(glm::cross(basis.forward, camera.up));
  if (basis.right == glm::vec3(0.0f)) return CameraBasis{};
  basis.up = glm::cross(basis.right, basis.forward);
  return basis;
}

Ray primary_ray(const Camera& camera, int width, int height, float image_x, float image_y) {
  const CameraBasis basis = camera_basis(camera);
  const glm::vec3 &forward = basis.forward, &right = basis.right, &up = basis.up;
  const float half_h = half_height_at_unit_depth(camera);
  const float half_w = half_h * static_cast<float>(width) / static_cast<float>(height);
  const float sx = (2.0f * image_x / static_cast<float>(width) - 1.0f) * half_w;
  const float sy = (1.0f - 2.0f * image_y / static_cast<float>(height)) * half_h;
  if (camera.orthographic()) {
    if (forward == glm::vec3(0.0f)) return {camera.position, glm::vec3(0.0f)};
    return {camera.position + sx * right + sy * up, forward};
  }
  return {camera.position, robust_normalize(forward + sx * right + sy * up)};
}

bool project_point(const Camera& camera, int width, int height, const glm::vec3& world,
                   glm::vec2& image, float& depth) {
  const CameraBasis basis = camera_basis(camera);
  const glm::vec3 d = world - camera.position;
  depth = glm::dot(d, basis.forward);
  if (!(depth > 0.0f)) return false;
  const float half_h = half_height_at_unit_depth(camera);
  const float half_w = half_h * static_cast<float>(width) / static_cast<float>(height);
  const float scale = camera.orthographic() ? 1.0f : depth;
  const float sx = glm::dot(d, basis.right) / scale;
  const float sy = glm::dot(d, basis.up) / scale;
  image.x = (sx / half_w + 1.0f) * 0.5f * static_cast<float>(width);
  image.y = (1.0f - sy / half_h) * 0.5f * static_cast<float>(height);
  return true;
}

}  // namespace renderer
