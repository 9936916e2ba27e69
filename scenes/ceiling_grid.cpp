#include "scenes/ceiling_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/generator_checks.h"
#include "scenes/scene_instantiation.h"
#include "scenes/seeded_random.h"

namespace scenes {
namespace {

const char* const kClassName = "ceiling grid";

}  // namespace

std::uint64_t ceiling_grid_light_count(int level) {
  return 1ull << (2 * level);
}

CeilingGridParams ceiling_grid_params(int level) {
  check_model_level("carpark", level, kCeilingGridMinLevel, kCeilingGridMaxLevel);

  CeilingGridParams p;
  p.columns = 1 << level;
  p.rows = 1 << level;
  return p;
}

SceneDescription describe_ceiling_grid_from(const CeilingGridParams& p) {
  check_generator_parameter(p.columns >= 1 && p.rows >= 1, kClassName,
                            "columns and rows must be >= 1", std::min(p.columns, p.rows));
  check_generator_parameter(p.spacing_m > 0.0f, kClassName, "spacing_m must be > 0", p.spacing_m);
  check_generator_parameter(p.ceiling_height_m > 1.0f, kClassName, "ceiling_height_m must be > 1",
                            p.ceiling_height_m);
  check_generator_parameter(p.bay_columns >= 1 && p.lane_rows >= 1, kClassName,
                            "bay_columns and lane_rows must be >= 1",
                            std::min(p.bay_columns, p.lane_rows));
  check_generator_parameter(p.intensity > 0.0f, kClassName, "intensity must be > 0", p.intensity);
  check_generator_parameter(p.car_share >= 0.0f && p.car_share <= 1.0f, kClassName,
                            "car_share must lie in [0, 1]", p.car_share);
  SceneDescription scene;
  scene.name = "carpark";
  scene.ambient = glm::vec3(0.15f);
  const std::uint32_t concrete = add_material(
      scene, "concrete", {{0.55f, 0.55f, 0.52f}, 0.1f, 0.7f, 0.05f, 10.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t ceiling = add_material(
      scene, "ceiling", {{0.7f, 0.7f, 0.68f}, 0.1f, 0.6f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t wall = add_material(
      scene, "partition", {{0.6f, 0.58f, 0.5f}, 0.1f, 0.65f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t pillar = add_material(
      scene, "pillar", {{0.75f, 0.7f, 0.2f}, 0.1f, 0.6f, 0.1f, 20.0f, 0.0f, 0.0f, 1.0f});
  std::vector<std::uint32_t> paints;
  const glm::vec3 paint_colours[] = {{0.7f, 0.1f, 0.1f},
                                     {0.1f, 0.2f, 0.6f},
                                     {0.8f, 0.8f, 0.82f},
                                     {0.1f, 0.1f, 0.1f},
                                     {0.3f, 0.5f, 0.3f}};
  for (int k = 0; k < 5; ++k) {
    paints.push_back(add_material(scene, "paint_" + std::to_string(k),
                                  {paint_colours[k], 0.1f, 0.5f, 0.6f, 60.0f, 0.0f, 0.0f, 1.0f}));
  }

  const float s = p.spacing_m, h = p.ceiling_height_m;
  const float width = s * static_cast<float>(p.columns), depth = s * static_cast<float>(p.rows);
  std::vector<SceneNode> parts;
  parts.push_back(quad_node(concrete, {-s, -s, 0.0f}, {width + 2.0f * s, 0.0f, 0.0f},
                            {0.0f, depth + 2.0f * s, 0.0f}));
  parts.push_back(quad_node(ceiling, {-s, -s, h}, {0.0f, depth + 2.0f * s, 0.0f},
                            {width + 2.0f * s, 0.0f, 0.0f}));
  // Light (i, j) hangs over the middle of bay (i, j), whose corner is (s i, s j).
  const auto lane = [&](int j) { return j % (p.lane_rows + 2) >= p.lane_rows; };
  // Partitions between bay columns, floor to ceiling, broken where a lane crosses; a pillar at
  // every wall end.
  for (int i = p.bay_columns; i < p.columns; i += p.bay_columns) {
    const float x = s * static_cast<float>(i);
    int j = 0;
    while (j < p.rows) {
      if (lane(j)) {
        ++j;
        continue;
      }
      const int start = j;
      while (j < p.rows && !lane(j)) ++j;
      const float y0 = s * static_cast<float>(start), y1 = s * static_cast<float>(j);
      parts.push_back(box_node(wall, {x - 0.1f, y0, 0.0f}, {x + 0.1f, y1, h}));
      parts.push_back(box_node(pillar, {x - 0.3f, y0 - 0.3f, 0.0f}, {x + 0.3f, y0 + 0.3f, h}));
      parts.push_back(box_node(pillar, {x - 0.3f, y1 - 0.3f, 0.0f}, {x + 0.3f, y1 + 0.3f, h}));
    }
  }
  SeededRandom random(p.seed);
  const glm::vec3 white{1.0f, 0.97f, 0.9f};
  for (int j = 0; j < p.rows; ++j) {
    for (int i = 0; i < p.columns; ++i) {
      const glm::vec3 centre{s * (static_cast<float>(i) + 0.5f), s * (static_cast<float>(j) + 0.5f),
                             0.0f};
      parts.push_back(
          translate_node(centre + glm::vec3(0.0f, 0.0f, h - 0.05f),
                         spot_light_node(p.intensity * white, p.cone_degrees, p.dropoff)));
      if (lane(j) || random.uniform(0.0f, 1.0f) >= p.car_share) continue;
      // A car along the bay: a body and a cabin, in one of the paints.
      const std::uint32_t paint = paints[random.next() % paints.size()];
      const glm::vec3 half{0.32f * s, 0.44f * s, 0.0f};
      parts.push_back(box_node(paint, centre - half + glm::vec3(0.0f, 0.0f, 0.2f),
                               centre + half + glm::vec3(0.0f, 0.0f, 0.85f)));
      parts.push_back(box_node(paint, centre - 0.6f * half + glm::vec3(0.0f, 0.0f, 0.85f),
                               centre + 0.6f * half + glm::vec3(0.0f, 0.0f, 1.35f)));
    }
  }
  scene.root = union_node(std::move(parts));

  // From a lane near the middle, at eye height, across the bays.
  const int lane_row = std::min(p.rows - 1, p.lane_rows);
  const float y = s * (static_cast<float>(lane_row) + 0.5f);
  scene.camera.position = {0.5f * s, y, 1.6f};
  scene.camera.target = {0.5f * s + 12.0f, y + 7.0f, 0.9f};
  scene.camera.vertical_fov_deg = 60.0f;
  return scene;
}

SceneDescription describe_ceiling_grid(int level) {
  SceneDescription s = describe_ceiling_grid_from(ceiling_grid_params(level));
  s.level = level;
  return s;
}

renderer::Scene build_ceiling_grid(int level) {
  return instantiate_scene(describe_ceiling_grid(level));
}

}  // namespace scenes
