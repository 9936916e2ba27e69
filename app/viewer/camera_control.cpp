#include "app/viewer/camera_control.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "scenes/scene_validation.h"

namespace app::viewer {
namespace {

constexpr float kMinDistance = 1e-3f;
// A moved camera's position, target and orthographic half height stay within a scene's bound, as
// the camera flags' do (app/camera_flags.h): Embree asserts on ray origins past about 1.8e18,
// which some 300 wheel notches out used to reach (SIGABRT).
constexpr float kMaxCameraCoordinate = scenes::kMaxCoordinate;

bool within_bound(const glm::vec3& v) {
  return std::abs(v.x) <= kMaxCameraCoordinate && std::abs(v.y) <= kMaxCameraCoordinate &&
         std::abs(v.z) <= kMaxCameraCoordinate;
}
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

bool camera_within_bounds(const renderer::Camera& camera) {
  return within_bound(camera.position) && within_bound(camera.target) &&
         camera.orthographic_half_height <= kMaxCameraCoordinate;
}

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
  return camera_within_bounds(result) ? result : camera;
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
  return camera_within_bounds(result) ? result : camera;
}

renderer::Camera zoom_camera(const renderer::Camera& camera, float factor) {
  const glm::vec3 offset = camera.position - camera.target;
  const float distance = glm::length(offset);
  if (distance <= 0.0f || !(factor > 0.0f)) return camera;
  float new_distance = std::max(distance * factor, kMinDistance);
  // Out to the bound at most: the eye stops where a coordinate (or the orthographic half height)
  // would pass it.
  const glm::vec3 dir = offset / distance;
  for (int i = 0; i < 3; ++i) {
    if (dir[i] == 0.0f) continue;
    const float room =
        kMaxCameraCoordinate - (dir[i] > 0.0f ? camera.target[i] : -camera.target[i]);
    new_distance = std::min(new_distance, 0.999f * room / std::abs(dir[i]));
  }
  if (camera.orthographic())
    new_distance = std::min(
        new_distance, 0.999f * distance * kMaxCameraCoordinate / camera.orthographic_half_height);
  renderer::Camera result = camera;
  result.position = camera.target + offset * (new_distance / distance);
  // An orthographic view does not change with distance: zooming narrows what it sees instead.
  if (camera.orthographic()) result.orthographic_half_height *= new_distance / distance;
  return new_distance > 0.0f && camera_within_bounds(result) ? result : camera;
}

}  // namespace app::viewer
