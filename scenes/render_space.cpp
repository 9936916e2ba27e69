#include "scenes/render_space.h"

#include <algorithm>
#include <utility>
#include <variant>

namespace scenes {

glm::vec3 render_space_origin(const renderer::Camera& camera) {
  const glm::vec3 reach3 = glm::abs(camera.position);
  const float reach = std::max(std::max(reach3.x, reach3.y), reach3.z);
  const float view = glm::length(camera.target - camera.position);
  if (reach < kRenderSpaceRebaseDistance || reach <= kRenderSpaceRebaseRatio * view)
    return glm::vec3(0.0f);
  return glm::round(camera.position);
}

void move_subtree(SceneNode& node, const glm::vec3& offset) {
  if (auto* a = std::get_if<Affine>(&node.data)) {
    a->translate += offset;
  } else if (std::holds_alternative<Union>(node.data)) {
    for (SceneNode& c : node.children) move_subtree(c, offset);
  } else if (auto* sphere = std::get_if<SphereShape>(&node.data)) {
    sphere->centre += offset;
  } else if (auto* box = std::get_if<BoxShape>(&node.data)) {
    box->lo += offset;
    box->hi += offset;
  } else if (auto* cylinder = std::get_if<CylinderShape>(&node.data)) {
    cylinder->a += offset;
    cylinder->b += offset;
  } else if (auto* quad = std::get_if<QuadShape>(&node.data)) {
    quad->corner += offset;
  } else {
    node = translate_node(offset, std::move(node));
  }
}

}  // namespace scenes
