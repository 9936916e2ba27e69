#include "scenes/robot.h"

#include <vector>

namespace scenes {

SceneNode robot_node(const RobotMaterials& m) {
  std::vector<SceneNode> parts;
  // Wheel: axis along x, resting on the floor.
  parts.push_back(cylinder_node(m.tyre, {-0.08f, 0.0f, 0.5f}, {0.08f, 0.0f, 0.5f}, 0.5f, 32));
  parts.push_back(cylinder_node(m.metal, {-0.1f, 0.0f, 0.5f}, {0.1f, 0.0f, 0.5f}, 0.1f, 12));
  // Fork and seat post.
  parts.push_back(cylinder_node(m.metal, {0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.3f}, 0.05f, 12));
  parts.push_back(box_node(m.metal, {-0.25f, -0.12f, 1.3f}, {0.25f, 0.12f, 1.36f}));
  // Body and arms (held out for balance).
  parts.push_back(box_node(m.body, {-0.3f, -0.2f, 1.36f}, {0.3f, 0.2f, 2.1f}));
  parts.push_back(cylinder_node(m.metal, {-0.3f, 0.0f, 1.95f}, {-0.85f, 0.15f, 1.75f}, 0.06f, 12));
  parts.push_back(cylinder_node(m.metal, {0.3f, 0.0f, 1.95f}, {0.85f, 0.15f, 1.75f}, 0.06f, 12));
  parts.push_back(cylinder_node(m.metal, {0.0f, 0.0f, 2.1f}, {0.0f, 0.0f, 2.2f}, 0.08f, 12));
  parts.push_back(sphere_node(m.head, {0.0f, 0.0f, 2.45f}, 0.27f));
  return union_node(std::move(parts));
}

}  // namespace scenes
