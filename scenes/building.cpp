#include "scenes/building.h"

#include <stdexcept>
#include <string>

#include "renderer/shapes.h"
#include "scenes/robot.h"

namespace scenes {
namespace {

constexpr float kHalfWall = 0.1f;  // each room owns half of every wall it shares
constexpr float kDoorWidth = 2.4f;
constexpr float kDoorHeight = 3.0f;

// A wall along x from (0, y0) to (kRoomSize, y1) with a centred doorway.
void add_wall_x(renderer::TriangleMesh& mesh, float y0, float y1) {
  const float d0 = 0.5f * (kRoomSize - kDoorWidth), d1 = 0.5f * (kRoomSize + kDoorWidth);
  renderer::add_box(mesh, {0.0f, y0, 0.0f}, {d0, y1, kWallHeight});
  renderer::add_box(mesh, {d1, y0, 0.0f}, {kRoomSize, y1, kWallHeight});
  renderer::add_box(mesh, {d0, y0, kDoorHeight}, {d1, y1, kWallHeight});
}

void add_wall_y(renderer::TriangleMesh& mesh, float x0, float x1) {
  const float d0 = 0.5f * (kRoomSize - kDoorWidth), d1 = 0.5f * (kRoomSize + kDoorWidth);
  renderer::add_box(mesh, {x0, 0.0f, 0.0f}, {x1, d0, kWallHeight});
  renderer::add_box(mesh, {x0, d1, 0.0f}, {x1, kRoomSize, kWallHeight});
  renderer::add_box(mesh, {x0, d0, kDoorHeight}, {x1, d1, kWallHeight});
}

renderer::Prototype make_room(const RobotMaterials& red, const RobotMaterials& blue,
                              std::uint32_t floor_material, std::uint32_t wall_material) {
  renderer::Prototype room;
  renderer::TriangleMesh floor;
  floor.material = floor_material;
  renderer::add_quad(floor, {0.0f, 0.0f, 0.0f}, {kRoomSize, 0.0f, 0.0f}, {0.0f, kRoomSize, 0.0f});
  room.meshes.push_back(floor);
  renderer::TriangleMesh walls;
  walls.material = wall_material;
  add_wall_x(walls, 0.0f, kHalfWall);
  add_wall_x(walls, kRoomSize - kHalfWall, kRoomSize);
  add_wall_y(walls, 0.0f, kHalfWall);
  add_wall_y(walls, kRoomSize - kHalfWall, kRoomSize);
  room.meshes.push_back(walls);
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  add_robot(room, lev::compose(lev::make_translation({3.2f, 3.6f, 0.0f}), lev::make_rotation(up, 0.6f)), red);
  add_robot(room, lev::compose(lev::make_translation({6.9f, 6.3f, 0.0f}), lev::make_rotation(up, 2.5f)), blue);
  return room;
}

}  // namespace

std::uint64_t building_light_count(int level) { return 1ull << (2 * level); }

renderer::Scene build_building(int level) {
  if (level < 1 || level > 10) throw std::invalid_argument("building level must be 1..10, got " + std::to_string(level));
  renderer::Scene scene;
  scene.name = "building";
  scene.level = level;
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.02f, 0.02f, 0.05f);

  // Materials.
  auto add_material = [&](renderer::Material m) {
    scene.materials.push_back(m);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
  };
  const std::uint32_t floor = add_material({{0.75f, 0.72f, 0.65f}, 0.1f, 0.7f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t wall = add_material({{0.85f, 0.8f, 0.7f}, 0.1f, 0.7f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t red = add_material({{0.8f, 0.15f, 0.1f}, 0.1f, 0.6f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t blue = add_material({{0.1f, 0.25f, 0.8f}, 0.1f, 0.6f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t chrome = add_material({{0.9f, 0.9f, 0.9f}, 0.05f, 0.15f, 0.8f, 80.0f, 0.6f, 0.0f, 1.0f});
  const std::uint32_t glass = add_material({{0.9f, 0.95f, 1.0f}, 0.02f, 0.05f, 0.6f, 100.0f, 0.1f, 0.8f, 1.5f});
  const std::uint32_t metal = add_material({{0.6f, 0.6f, 0.65f}, 0.1f, 0.4f, 0.5f, 30.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t tyre = add_material({{0.12f, 0.12f, 0.12f}, 0.1f, 0.5f, 0.1f, 10.0f, 0.0f, 0.0f, 1.0f});

  // Geometry: one room prototype placed once per room.
  scene.geometry.prototypes.push_back(make_room({red, chrome, metal, tyre}, {blue, glass, metal, tyre}, floor, wall));
  const int rooms_per_side = 1 << level;
  scene.geometry.instances.reserve(static_cast<std::size_t>(rooms_per_side) * rooms_per_side);
  for (int y = 0; y < rooms_per_side; ++y) {
    for (int x = 0; x < rooms_per_side; ++x) {
      scene.geometry.instances.push_back(
          {0, lev::make_translation({kRoomSize * static_cast<float>(x), kRoomSize * static_cast<float>(y), 0.0f})});
    }
  }

  // Lights (thesis fig. 3.4): master 0 is a room's light; master k places four copies of
  // master k-1 in a 2x2 block; the root instances master `level`.
  lev::LightTree& tree = scene.light_tree;
  tree.masters.push_back(lev::light_node(lev::make_point_light(
      {0.5f * kRoomSize, 0.5f * kRoomSize, kCeilingLightHeight},
      kCeilingLightIntensity * glm::vec3(1.0f, 0.95f, 0.85f))));
  tree.master_names.push_back("room");
  for (int k = 1; k <= level; ++k) {
    const float block = kRoomSize * static_cast<float>(1 << (k - 1));
    std::vector<lev::LightTreeNode> quarters;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        quarters.push_back(lev::affine_node(
            lev::make_translation({block * static_cast<float>(i), block * static_cast<float>(j), 0.0f}),
            lev::instance_node(static_cast<std::uint32_t>(k - 1))));
      }
    }
    tree.masters.push_back(lev::union_node(std::move(quarters)));
    tree.master_names.push_back("block" + std::to_string(k));
  }
  tree.root = lev::instance_node(static_cast<std::uint32_t>(level));
  scene.lights = lev::build_hierarchy(tree, 0.01f);

  // Camera: the whole building from the south, above, as in thesis fig. 5.1.
  const float width = kRoomSize * static_cast<float>(rooms_per_side);
  scene.camera.target = {0.5f * width, 0.47f * width, 0.0f};
  scene.camera.position = {0.5f * width, -0.32f * width, 0.82f * width};
  scene.camera.up = {0.0f, 0.0f, 1.0f};
  scene.camera.vertical_fov_deg = 45.0f;
  return scene;
}

}  // namespace scenes
