#include "scenes/maze.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/robot.h"
#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

enum class Side { minus_x, plus_x, minus_y, plus_y };

// The half of a wall that cell (i, j) owns on one side.
SceneNode half_wall(std::uint32_t material, int i, int j, Side side) {
  const float x0 = kMazeCell * static_cast<float>(i), y0 = kMazeCell * static_cast<float>(j);
  const float x1 = x0 + kMazeCell, y1 = y0 + kMazeCell, t = kMazeHalfWall, h = kMazeWallHeight;
  switch (side) {
    case Side::minus_x:
      return box_node(material, {x0, y0, 0.0f}, {x0 + t, y1, h});
    case Side::plus_x:
      return box_node(material, {x1 - t, y0, 0.0f}, {x1, y1, h});
    case Side::minus_y:
      return box_node(material, {x0, y0, 0.0f}, {x1, y0 + t, h});
    case Side::plus_y:
      break;
  }
  return box_node(material, {x0, y1 - t, 0.0f}, {x1, y1, h});
}

SceneNode placed(const glm::vec3& at, float degrees_about_z, SceneNode child) {
  Affine a;
  a.translate = at;
  a.rotate_degrees = degrees_about_z;
  return affine_node(a, std::move(child));
}

glm::vec3 cell_centre(int i, int j) {
  return {kMazeCell * (static_cast<float>(i) + 0.5f), kMazeCell * (static_cast<float>(j) + 0.5f),
          0.0f};
}

// The corridor segment from the centre of cell (i, j) to its neighbour in +x (or +y).
SceneNode segment_at(std::uint32_t segment, int i, int j, bool along_y) {
  return placed(cell_centre(i, j), along_y ? 90.0f : 0.0f, instance_node(segment));
}

}  // namespace

std::uint64_t maze_light_count(int level) {
  return 3ull * ((1ull << (2 * (level + 1))) - 1ull);
}

SceneDescription describe_maze(int level) {
  if (level < kMazeMinLevel || level > kMazeMaxLevel) {
    throw std::invalid_argument("maze level must be " + std::to_string(kMazeMinLevel) + ".." +
                                std::to_string(kMazeMaxLevel) + ", got " + std::to_string(level));
  }
  SceneDescription scene;
  scene.name = "maze";
  scene.level = level;
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.01f, 0.01f, 0.03f);

  const std::uint32_t ground = add_material(
      scene, "ground", {{0.85f, 0.85f, 0.9f}, 0.12f, 0.9f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t hedge = add_material(
      scene, "hedge", {{0.6f, 0.85f, 0.5f}, 0.15f, 0.9f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t red =
      add_material(scene, "red", {{0.9f, 0.2f, 0.15f}, 0.1f, 0.8f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t blue = add_material(
      scene, "blue", {{0.2f, 0.35f, 0.95f}, 0.1f, 0.8f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t yellow = add_material(
      scene, "yellow", {{0.95f, 0.8f, 0.2f}, 0.1f, 0.8f, 0.4f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t chrome = add_material(
      scene, "chrome", {{0.9f, 0.9f, 0.9f}, 0.05f, 0.15f, 0.8f, 80.0f, 0.6f, 0.0f, 1.0f});
  const std::uint32_t metal = add_material(
      scene, "metal", {{0.6f, 0.6f, 0.65f}, 0.1f, 0.5f, 0.5f, 30.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t tyre = add_material(
      scene, "tyre", {{0.12f, 0.12f, 0.12f}, 0.1f, 0.5f, 0.1f, 10.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t lamp =
      add_material(scene, "lamp", {{1.0f, 0.85f, 0.5f}, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});

  const std::uint32_t robots[3] = {
      add_master(scene, "robot_red", robot_node({red, chrome, metal, tyre})),
      add_master(scene, "robot_blue", robot_node({blue, chrome, metal, tyre})),
      add_master(scene, "robot_yellow", robot_node({yellow, chrome, metal, tyre}))};

  // A streetlight in a corridor running along x: pole at the side, arm over the corridor, the
  // light under a shade just off the centre line.
  const float h = kStreetlightHeight;
  const std::uint32_t pole = add_master(
      scene, "lamp_post",
      union_node(
          {cylinder_node(metal, {0.0f, -2.2f, 0.0f}, {0.0f, -2.2f, h + 0.3f}, 0.07f, 12),
           cylinder_node(metal, {0.0f, -2.2f, h + 0.3f}, {0.0f, -0.5f, h + 0.3f}, 0.05f, 12),
           cylinder_node(lamp, {0.0f, -0.3f, h + 0.06f}, {0.0f, -0.3f, h + 0.3f}, 0.22f, 16)}));

  // One segment of the corridor, from a cell centre to the next: three robots, each under its
  // own streetlight, a third of a cell apart (so the spacing is the same around corners).
  std::vector<SceneNode> posts;
  for (int k = 0; k < 3; ++k) {
    Affine robot_frame;
    robot_frame.translate = {0.0f, 0.45f, 0.0f};
    robot_frame.rotate_degrees = -90.0f;  // facing along the corridor, arms across it
    robot_frame.scale = 0.8f;
    posts.push_back(translate_node(
        {kMazeCell * (static_cast<float>(2 * k + 1) / 6.0f), 0.0f, 0.0f},
        union_node(
            {affine_node(robot_frame, instance_node(robots[k])), instance_node(pole),
             translate_node({0.0f, -0.3f, h},
                            spot_light_node(kStreetlightIntensity * glm::vec3(1.0f, 0.9f, 0.7f),
                                            kStreetlightConeDegrees, kStreetlightDropoff))})));
  }
  const std::uint32_t segment = add_master(scene, "segment", union_node(std::move(posts)));

  // Order 1: cells (0,0) -> (0,1) -> (1,1) -> (1,0); walls everywhere the curve does not pass,
  // except the entry (-x, -y of the first cell) and exit (+x, -y of the last), which the block
  // above closes or joins.
  std::uint32_t curve = add_master(
      scene, "curve1",
      union_node({half_wall(hedge, 0, 0, Side::plus_x), half_wall(hedge, 0, 1, Side::minus_x),
                  half_wall(hedge, 0, 1, Side::plus_y), half_wall(hedge, 1, 1, Side::plus_x),
                  half_wall(hedge, 1, 1, Side::plus_y), half_wall(hedge, 1, 0, Side::minus_x),
                  segment_at(segment, 0, 0, true), segment_at(segment, 0, 1, false),
                  segment_at(segment, 1, 0, true)}));
  // Order k: the lower-left quarter is the order k-1 curve mirrored on the diagonal and the
  // lower-right on the other diagonal; every block is symmetric under x -> size - x (its walls,
  // lights and open sides), so a quarter turn places the same walls and lights as the mirror.
  for (int k = 2; k <= level + 1; ++k) {
    const int n = 1 << (k - 1);  // cells per side of a quarter
    const float s = kMazeCell * static_cast<float>(n);
    std::vector<SceneNode> parts;
    parts.push_back(placed({0.0f, s, 0.0f}, -90.0f, instance_node(curve)));
    parts.push_back(translate_node({0.0f, s, 0.0f}, instance_node(curve)));
    parts.push_back(translate_node({s, s, 0.0f}, instance_node(curve)));
    parts.push_back(placed({2.0f * s, 0.0f, 0.0f}, 90.0f, instance_node(curve)));
    parts.push_back(segment_at(segment, 0, n - 1, true));
    parts.push_back(segment_at(segment, n - 1, n, false));
    parts.push_back(segment_at(segment, 2 * n - 1, n - 1, true));
    // The quarters' open corners that face the outside or a quarter they do not join.
    parts.push_back(half_wall(hedge, 0, n - 1, Side::minus_x));
    parts.push_back(half_wall(hedge, 0, n, Side::minus_x));
    parts.push_back(half_wall(hedge, n - 1, n, Side::minus_y));
    parts.push_back(half_wall(hedge, n, n, Side::minus_y));
    parts.push_back(half_wall(hedge, 2 * n - 1, n, Side::plus_x));
    parts.push_back(half_wall(hedge, 2 * n - 1, n - 1, Side::plus_x));
    curve = add_master(scene, "curve" + std::to_string(k), union_node(std::move(parts)));
  }

  // The maze: ground, the curve, and the outer walls beside the entrance and the exit, which
  // stay open to the south.
  const int cells = 1 << (level + 1);
  const float width = kMazeCell * static_cast<float>(cells);
  const float margin = 0.0f;
  scene.root =
      union_node({quad_node(ground, {-margin, -margin, 0.0f}, {width + 2.0f * margin, 0.0f, 0.0f},
                            {0.0f, width + 2.0f * margin, 0.0f}),
                  instance_node(curve), half_wall(hedge, 0, 0, Side::minus_x),
                  half_wall(hedge, cells - 1, 0, Side::plus_x)});

  // Straight down on the whole maze (thesis fig. 5.2).
  scene.camera.target = {0.5f * width, 0.5f * width, 0.0f};
  scene.camera.position = {0.5f * width, 0.5f * width, 1.32f * width};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = 45.0f;
  return scene;
}

renderer::Scene build_maze(int level) {
  return instantiate_scene(describe_maze(level));
}

}  // namespace scenes
