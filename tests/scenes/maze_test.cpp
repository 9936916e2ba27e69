#include "scenes/maze.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_models.h"

namespace {

using Wall = std::tuple<int, int, int>;  // cell x, cell y, side: 0 -x, 1 +x, 2 -y, 3 +y

// The order-n Hilbert curve's d-th cell (the classic iterative d2xy): starts at (0, 0) and ends
// at (2^n - 1, 0), as the maze does.
std::pair<int, int> hilbert_cell(int side, int d) {
  int x = 0, y = 0;
  for (int s = 1; s < side; s *= 2) {
    const int rx = 1 & (d / 2), ry = 1 & (d ^ rx);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - x;
        y = s - 1 - y;
      }
      std::swap(x, y);
    }
    x += s * rx;
    y += s * ry;
    d /= 4;
  }
  return {x, y};
}

std::set<Wall> expected_walls(int level) {
  const int side = 1 << (level + 1);
  std::set<Wall> walls;
  for (int x = 0; x < side; ++x) {
    for (int y = 0; y < side; ++y) {
      for (int s = 0; s < 4; ++s) walls.insert({x, y, s});
    }
  }
  // The corridor crosses the wall between consecutive cells; the maze opens south at both ends.
  for (int d = 0; d + 1 < side * side; ++d) {
    const auto [x0, y0] = hilbert_cell(side, d);
    const auto [x1, y1] = hilbert_cell(side, d + 1);
    const int dx = x1 - x0, dy = y1 - y0;
    const int out = dx == 1 ? 1 : dx == -1 ? 0 : dy == 1 ? 3 : 2;
    walls.erase({x0, y0, out});
    walls.erase({x1, y1, out ^ 1});
  }
  walls.erase({0, 0, 2});
  walls.erase({side - 1, 0, 2});
  return walls;
}

// Every box of the description in world space, instances expanded.
void collect_boxes(const scenes::SceneDescription& scene, const scenes::SceneNode& node,
                   const lev::Similarity& xf, std::uint32_t material,
                   std::vector<std::pair<glm::vec3, glm::vec3>>& boxes) {
  if (const auto* a = std::get_if<scenes::Affine>(&node.data)) {
    collect_boxes(scene, node.children[0], lev::compose(xf, scenes::affine_similarity(*a)),
                  material, boxes);
  } else if (const auto* in = std::get_if<scenes::Instance>(&node.data)) {
    collect_boxes(scene, scene.masters[in->master].node, xf, material, boxes);
  } else if (const auto* b = std::get_if<scenes::BoxShape>(&node.data)) {
    if (b->material != material) return;
    const glm::vec3 p = lev::apply_point(xf, b->lo), q = lev::apply_point(xf, b->hi);
    boxes.push_back({glm::min(p, q), glm::max(p, q)});
  } else {
    for (const scenes::SceneNode& c : node.children) collect_boxes(scene, c, xf, material, boxes);
  }
}

std::set<Wall> built_walls(int level) {
  const scenes::SceneDescription scene = scenes::describe_maze(level);
  std::uint32_t hedge = 0;
  while (scene.materials[hedge].name != "hedge") ++hedge;
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes;
  collect_boxes(scene, scene.root, lev::Similarity{}, hedge, boxes);
  std::set<Wall> walls;
  const float c = scenes::kMazeCell;
  for (const auto& [lo, hi] : boxes) {
    const glm::vec3 centre = 0.5f * (lo + hi), size = hi - lo;
    const int x = static_cast<int>(std::floor(centre.x / c)),
              y = static_cast<int>(std::floor(centre.y / c));
    const bool thin_x = size.x < 0.5f * c;
    EXPECT_NEAR(thin_x ? size.y : size.x, c, 1e-3f);
    EXPECT_NEAR(thin_x ? size.x : size.y, scenes::kMazeHalfWall, 1e-3f);
    const float fraction =
        thin_x ? centre.x / c - static_cast<float>(x) : centre.y / c - static_cast<float>(y);
    const int side = (thin_x ? 0 : 2) + (fraction > 0.5f ? 1 : 0);
    EXPECT_TRUE(walls.insert({x, y, side}).second)
        << "wall twice at " << x << " " << y << " " << side;
  }
  return walls;
}

TEST(Maze, LightCountsPerLevel) {
  const std::uint64_t expected[] = {45, 189, 765, 3069, 12285};
  for (int level = 1; level <= 5; ++level) {
    EXPECT_EQ(scenes::maze_light_count(level), expected[level - 1]);
    const renderer::Scene scene = scenes::build_maze(level);
    EXPECT_EQ(scene.lights.light_count, expected[level - 1]);
    EXPECT_EQ(lev::flatten_lights(scene.lights).size(), expected[level - 1]);
  }
  for (int level = 6; level <= scenes::kMazeMaxLevel; ++level) {
    EXPECT_EQ(scenes::maze_light_count(level), 3 * ((1ull << (2 * level + 2)) - 1));
  }
  EXPECT_EQ(scenes::build_maze(6).lights.light_count, 49149u);
  const scenes::SceneModel* model = scenes::find_scene_model("maze");
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(scenes::level_for_light_count(*model, 12285), 5);
  EXPECT_EQ(scenes::level_for_light_count(*model, 64), -1);
}

TEST(Maze, HierarchyGrowsByAConstantPerLevel) {
  std::vector<std::size_t> bytes;
  for (int level = 1; level <= 7; ++level)
    bytes.push_back(lev::hierarchy_bytes(scenes::build_maze(level).lights));
  const std::size_t step = bytes[1] - bytes[0];
  EXPECT_GT(step, 0u);
  for (std::size_t i = 1; i < bytes.size(); ++i)
    EXPECT_EQ(bytes[i] - bytes[i - 1], step) << "level " << i + 1;
  EXPECT_LT(bytes.back(), 16u * 1024u);
}

TEST(Maze, WallsStandWhereverTheHilbertCurveDoesNotPass) {
  for (int level = 1; level <= 3; ++level)
    EXPECT_EQ(built_walls(level), expected_walls(level)) << "level " << level;
}

TEST(Maze, EveryStreetlightHangsOverTheCorridorAndShinesDown) {
  const int level = 2;
  const int side = 1 << (level + 1);
  std::vector<glm::vec2> centres;
  for (int d = 0; d < side * side; ++d) {
    const auto [x, y] = hilbert_cell(side, d);
    centres.push_back(scenes::kMazeCell *
                      glm::vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  }
  const renderer::Scene scene = scenes::build_maze(level);
  for (const lev::Light& l : lev::flatten_lights(scene.lights)) {
    EXPECT_FLOAT_EQ(l.position.z, scenes::kStreetlightHeight);
    ASSERT_EQ(l.kind, lev::LightKind::spot);
    EXPECT_NEAR(l.direction.z, -1.0f, 1e-6f);
    EXPECT_NEAR(std::acos(l.cos_cone_half_angle), glm::radians(scenes::kStreetlightConeDegrees),
                1e-5f);
    // Within the lamp's offset (0.3) of the curve through the cell centres.
    float nearest = 1e9f;
    const glm::vec2 p(l.position.x, l.position.y);
    for (std::size_t d = 0; d + 1 < centres.size(); ++d) {
      const glm::vec2 a = centres[d], b = centres[d + 1];
      const float t = glm::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
      nearest = std::min(nearest, glm::length(p - (a + t * (b - a))));
    }
    EXPECT_LT(nearest, 0.31f) << l.position.x << " " << l.position.y;
  }
}

TEST(Maze, RejectsLevelsOutOfRange) {
  EXPECT_THROW(scenes::describe_maze(0), std::invalid_argument);
  EXPECT_THROW(scenes::describe_maze(scenes::kMazeMaxLevel + 1), std::invalid_argument);
}

}  // namespace
