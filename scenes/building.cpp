#include "scenes/building.h"

#include <stdexcept>
#include <string>

#include "scenes/robot.h"
#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

constexpr float kHalfWall = 0.1f;  // each room owns half of every wall it shares
constexpr float kDoorWidth = 2.4f;
constexpr float kDoorHeight = 3.0f;
// The two robots of a room face 0.6 and 2.5 radians about z (in degrees, as Affine takes them).
constexpr float kRedRobotHeadingDeg = 34.3774677f;
constexpr float kBlueRobotHeadingDeg = 143.239449f;

// A wall along x from (0, y0) to (kRoomSize, y1) with a centred doorway.
void add_wall_x(std::vector<SceneNode>& parts, std::uint32_t material, float y0, float y1) {
  const float d0 = 0.5f * (kRoomSize - kDoorWidth), d1 = 0.5f * (kRoomSize + kDoorWidth);
  parts.push_back(box_node(material, {0.0f, y0, 0.0f}, {d0, y1, kWallHeight}));
  parts.push_back(box_node(material, {d1, y0, 0.0f}, {kRoomSize, y1, kWallHeight}));
  parts.push_back(box_node(material, {d0, y0, kDoorHeight}, {d1, y1, kWallHeight}));
}

void add_wall_y(std::vector<SceneNode>& parts, std::uint32_t material, float x0, float x1) {
  const float d0 = 0.5f * (kRoomSize - kDoorWidth), d1 = 0.5f * (kRoomSize + kDoorWidth);
  parts.push_back(box_node(material, {x0, 0.0f, 0.0f}, {x1, d0, kWallHeight}));
  parts.push_back(box_node(material, {x0, d1, 0.0f}, {x1, kRoomSize, kWallHeight}));
  parts.push_back(box_node(material, {x0, d0, kDoorHeight}, {x1, d1, kWallHeight}));
}

SceneNode placed(const glm::vec3& at, float degrees_about_z, SceneNode child) {
  Affine a;
  a.translate = at;
  a.rotate_degrees = degrees_about_z;
  return affine_node(a, std::move(child));
}

}  // namespace

std::uint64_t building_light_count(int level) {
  return 1ull << (2 * level);
}

SceneDescription describe_building(int level) {
  if (level < kBuildingMinLevel || level > kBuildingMaxLevel) {
    throw std::invalid_argument("building level must be " + std::to_string(kBuildingMinLevel) +
                                ".." + std::to_string(kBuildingMaxLevel) + ", got " +
                                std::to_string(level));
  }
  SceneDescription scene;
  scene.name = "building";
  scene.level = level;
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.02f, 0.02f, 0.05f);

  const std::uint32_t floor = add_material(
      scene, "floor", {{0.75f, 0.72f, 0.65f}, 0.1f, 0.7f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t wall =
      add_material(scene, "wall", {{0.85f, 0.8f, 0.7f}, 0.1f, 0.7f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t red =
      add_material(scene, "red", {{0.8f, 0.15f, 0.1f}, 0.1f, 0.6f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t blue =
      add_material(scene, "blue", {{0.1f, 0.25f, 0.8f}, 0.1f, 0.6f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t chrome = add_material(
      scene, "chrome", {{0.9f, 0.9f, 0.9f}, 0.05f, 0.15f, 0.8f, 80.0f, 0.6f, 0.0f, 1.0f});
  const std::uint32_t glass = add_material(
      scene, "glass", {{0.9f, 0.95f, 1.0f}, 0.02f, 0.05f, 0.6f, 100.0f, 0.1f, 0.8f, 1.5f});
  const std::uint32_t metal = add_material(
      scene, "metal", {{0.6f, 0.6f, 0.65f}, 0.1f, 0.4f, 0.5f, 30.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t tyre = add_material(
      scene, "tyre", {{0.12f, 0.12f, 0.12f}, 0.1f, 0.5f, 0.1f, 10.0f, 0.0f, 0.0f, 1.0f});

  const std::uint32_t red_robot =
      add_master(scene, "robot_red", robot_node({red, chrome, metal, tyre}));
  const std::uint32_t blue_robot =
      add_master(scene, "robot_blue", robot_node({blue, glass, metal, tyre}));

  // A room: floor, walls with doorways, two robots and one ceiling light (thesis 5.3).
  std::vector<SceneNode> room;
  room.push_back(
      quad_node(floor, {0.0f, 0.0f, 0.0f}, {kRoomSize, 0.0f, 0.0f}, {0.0f, kRoomSize, 0.0f}));
  add_wall_x(room, wall, 0.0f, kHalfWall);
  add_wall_x(room, wall, kRoomSize - kHalfWall, kRoomSize);
  add_wall_y(room, wall, 0.0f, kHalfWall);
  add_wall_y(room, wall, kRoomSize - kHalfWall, kRoomSize);
  room.push_back(placed({3.2f, 3.6f, 0.0f}, kRedRobotHeadingDeg, instance_node(red_robot)));
  room.push_back(placed({6.9f, 6.3f, 0.0f}, kBlueRobotHeadingDeg, instance_node(blue_robot)));
  room.push_back(
      translate_node({0.5f * kRoomSize, 0.5f * kRoomSize, kCeilingLightHeight},
                     point_light_node(kCeilingLightIntensity * glm::vec3(1.0f, 0.95f, 0.85f))));
  std::uint32_t block = add_master(scene, "room", union_node(std::move(room)));

  // Thesis fig. 3.4: block k places four copies of block k-1 in a 2x2 square.
  for (int k = 1; k <= level; ++k) {
    const float size = kRoomSize * static_cast<float>(1 << (k - 1));
    std::vector<SceneNode> quarters;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        quarters.push_back(
            translate_node({size * static_cast<float>(i), size * static_cast<float>(j), 0.0f},
                           instance_node(block)));
      }
    }
    block = add_master(scene, "block" + std::to_string(k), union_node(std::move(quarters)));
  }
  scene.root = instance_node(block);

  // The whole building from the south, above, as in thesis fig. 5.1.
  const float width = kRoomSize * static_cast<float>(1 << level);
  scene.camera.target = {0.5f * width, 0.47f * width, 0.0f};
  scene.camera.position = {0.5f * width, -0.32f * width, 0.82f * width};
  scene.camera.up = {0.0f, 0.0f, 1.0f};
  scene.camera.vertical_fov_deg = 45.0f;
  return scene;
}

renderer::Scene build_building(int level) {
  return instantiate_scene(describe_building(level));
}

}  // namespace scenes
