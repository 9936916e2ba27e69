#include "app/viewer/camera_control.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace app::viewer {
namespace {

constexpr float kMinDistance = 1e-3f;
constexpr float kPoleMargin = 0.02f;  // radians kept between the view direction and the up axis

glm::vec3 unit_up(const renderer::Camera& camera) {
  const float length = glm::length(camera.up);
  return length > 0.0f ? camera.up / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 a =
      std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::normalize(glm::cross(n, a));
}

}  // namespace

renderer::Camera orbit_camera(const renderer::Camera& camera, float yaw, float pitch) {
  const glm::vec3 up = unit_up(camera);
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  if (distance <= 0.0f) return camera;
  const glm::vec3 dir = offset / distance;
  // Spherical coordinates about `up`: polar angle from up, azimuth in a frame around it.
  const float polar = std::acos(std::clamp(glm::dot(dir, up), -1.0f, 1.0f));
  glm::vec3 horizontal = dir - glm::dot(dir, up) * up;
  const float h = glm::length(horizontal);
  horizontal = h > 1e-6f ? horizontal / h : perpendicular(up);
  const glm::vec3 side = glm::cross(up, horizontal);
  const float new_polar = std::clamp(polar - pitch, kPoleMargin, glm::pi<float>() - kPoleMargin);
  const glm::vec3 turned = std::cos(yaw) * horizontal + std::sin(yaw) * side;
  const glm::vec3 new_dir = std::cos(new_polar) * up + std::sin(new_polar) * turned;
  renderer::Camera result = camera;
  result.position = camera.target + distance * new_dir;
  return result;
}

renderer::Camera pan_camera(const renderer::Camera& camera, float right, float up) {
  const glm::vec3 forward_raw = camera.target - camera.position;
  const float distance = glm::length(forward_raw);
  if (distance <= 0.0f) return camera;
  const glm::vec3 forward = forward_raw / distance;
  glm::vec3 right_axis = glm::cross(forward, unit_up(camera));
  const float r = glm::length(right_axis);
  right_axis = r > 1e-6f ? right_axis / r : perpendicular(forward);
  const glm::vec3 up_axis = glm::cross(right_axis, forward);
  const float visible_height =
      camera.orthographic()
          ? 2.0f * camera.orthographic_half_height
          : 2.0f * distance * std::tan(glm::radians(camera.vertical_fov_deg) * 0.5f);
  const glm::vec3 move = visible_height * (right * right_axis + up * up_axis);
  renderer::Camera result = camera;
  result.position += move;
  result.target += move;
  return result;
}

renderer::Camera zoom_camera(const renderer::Camera& camera, float factor) {
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  if (distance <= 0.0f || !(factor > 0.0f)) return camera;
  const float new_distance = std::max(distance * factor, kMinDistance);
  renderer::Camera result = camera;
  result.position = camera.target + offset * (new_distance / distance);
  // An orthographic view does not change with distance: zooming narrows what it sees instead.
  if (camera.orthographic()) result.orthographic_half_height *= new_distance / distance;
  return result;
}

}  // namespace app::viewer
