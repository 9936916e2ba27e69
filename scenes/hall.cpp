#include "scenes/hall.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/robot.h"
#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

constexpr float kHalfWidth = 16.0f;  // the hall spans x in [-16, 16]
constexpr float kFront = -22.0f;     // the audience side
constexpr float kBack = 17.0f;
constexpr float kCeiling = 13.5f;
constexpr float kStageHeight = 0.8f;
const glm::vec3 kStageCentre{0.0f, 5.0f, kStageHeight};

}  // namespace

std::uint64_t hall_light_count(int level) {
  return 1ull << (2 * level);
}

SceneDescription describe_hall(int level) {
  if (level < kHallMinLevel || level > kHallMaxLevel) {
    throw std::invalid_argument("hall level must be " + std::to_string(kHallMinLevel) + ".." +
                                std::to_string(kHallMaxLevel) + ", got " + std::to_string(level));
  }
  SceneDescription scene;
  scene.name = "hall";
  scene.level = level;
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.0f);

  const std::uint32_t stage = add_material(
      scene, "stage", {{0.55f, 0.4f, 0.28f}, 0.1f, 0.16f, 0.1f, 20.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t carpet = add_material(
      scene, "carpet", {{0.5f, 0.12f, 0.12f}, 0.1f, 0.25f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t wall = add_material(
      scene, "wall", {{0.35f, 0.3f, 0.32f}, 0.1f, 0.25f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t red =
      add_material(scene, "red", {{0.8f, 0.15f, 0.1f}, 0.1f, 0.18f, 0.3f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t green = add_material(
      scene, "green", {{0.15f, 0.7f, 0.2f}, 0.1f, 0.18f, 0.3f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t blue = add_material(
      scene, "blue", {{0.1f, 0.25f, 0.8f}, 0.1f, 0.18f, 0.3f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t chrome = add_material(
      scene, "chrome", {{0.9f, 0.9f, 0.9f}, 0.05f, 0.05f, 0.3f, 80.0f, 0.5f, 0.0f, 1.0f});
  const std::uint32_t metal = add_material(
      scene, "metal", {{0.6f, 0.6f, 0.65f}, 0.1f, 0.12f, 0.3f, 30.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t tyre = add_material(
      scene, "tyre", {{0.12f, 0.12f, 0.12f}, 0.1f, 0.2f, 0.05f, 10.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t can = add_material(
      scene, "can", {{0.15f, 0.15f, 0.17f}, 0.3f, 0.5f, 0.6f, 30.0f, 0.0f, 0.0f, 1.0f});

  const std::uint32_t robots[3] = {
      add_master(scene, "robot_red", robot_node({red, chrome, metal, tyre})),
      add_master(scene, "robot_green", robot_node({green, chrome, metal, tyre})),
      add_master(scene, "robot_blue", robot_node({blue, chrome, metal, tyre}))};

  // A spotlight and its can, the light at the can's mouth shining down (-z), at the size of the
  // level's smallest fixture: each split halves the scale and so quarters the intensity (thesis
  // 4.2.2), and the light folds that scale into itself.
  const int splits = level - kHallMinLevel;
  Affine shrink;
  shrink.scale = std::ldexp(1.0f, -splits);
  const SceneNode spot = affine_node(
      shrink, union_node({cylinder_node(can, {0.0f, 0.0f, 0.05f}, {0.0f, 0.0f, 0.9f}, 0.35f, 16),
                          spot_light_node(kSpotIntensity * glm::vec3(1.0f, 0.95f, 0.85f),
                                          kSpotConeDegrees, kSpotDropoff)}));
  // Each level splits a spotlight into four, in the four quarters of its place in the grid, with
  // the same cone and the same aim. The fixtures are built from the smallest up at their final
  // size, so that every split is a pure translation: the walk then tests each quarter's box once,
  // where a scaled instance would have its master's box tested again. The smallest split holds
  // its four spots themselves rather than instances of one: a light in a union gets its exact
  // test straight away, where an instance would first have its box tested, and that box contains
  // nearly every point the four spots' common box does.
  std::uint32_t fixture = 0;
  for (int k = 1; k <= splits; ++k) {
    const float offset = 0.25f * kRigSpacing * std::ldexp(1.0f, k - splits);
    std::vector<SceneNode> quarters;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const glm::vec3 t{offset * (2.0f * static_cast<float>(i) - 1.0f),
                          offset * (2.0f * static_cast<float>(j) - 1.0f), 0.0f};
        quarters.push_back(translate_node(t, k == 1 ? spot : instance_node(fixture)));
      }
    }
    fixture = add_master(scene, "spots" + std::to_string(k), union_node(std::move(quarters)));
  }

  std::vector<SceneNode> parts;
  // The hall: carpet, stage, walls and ceiling.
  parts.push_back(quad_node(carpet, {-kHalfWidth, kFront, 0.0f}, {2.0f * kHalfWidth, 0.0f, 0.0f},
                            {0.0f, kBack - kFront, 0.0f}));
  parts.push_back(box_node(stage, {-11.0f, -2.0f, 0.0f}, {11.0f, kBack, kStageHeight}));
  parts.push_back(quad_node(wall, {-kHalfWidth, kBack, 0.0f}, {2.0f * kHalfWidth, 0.0f, 0.0f},
                            {0.0f, 0.0f, kCeiling}));
  parts.push_back(quad_node(wall, {-kHalfWidth, kFront, 0.0f}, {0.0f, kBack - kFront, 0.0f},
                            {0.0f, 0.0f, kCeiling}));
  parts.push_back(quad_node(wall, {kHalfWidth, kFront, 0.0f}, {0.0f, 0.0f, kCeiling},
                            {0.0f, kBack - kFront, 0.0f}));
  parts.push_back(quad_node(wall, {-kHalfWidth, kFront, kCeiling}, {0.0f, kBack - kFront, 0.0f},
                            {2.0f * kHalfWidth, 0.0f, 0.0f}));
  // Three robots facing the audience.
  const glm::vec3 places[3] = {
      {-4.5f, 4.0f, kStageHeight}, {0.0f, 6.5f, kStageHeight}, {4.5f, 4.0f, kStageHeight}};
  for (int r = 0; r < 3; ++r) {
    Affine a;
    a.translate = places[r];
    a.rotate_degrees = 180.0f + 20.0f * static_cast<float>(r - 1);
    parts.push_back(affine_node(a, instance_node(robots[r])));
  }
  // The rig: 8x8 places over the stage, each aimed at its centre, grouped 2x2 into blocks and
  // the blocks 2x2 into quadrants. A group is a master instanced once, only so that its box is
  // tested before its fixtures' (a union has no box of its own): a point below the rig's reach
  // then tests four boxes, not 64.
  const auto fixture_at = [&](int i, int j) {
    const glm::vec3 at{kRigSpacing * (static_cast<float>(i) - 3.5f),
                       kStageCentre.y + kRigSpacing * (static_cast<float>(j) - 3.5f), kRigHeight};
    // Unsplit (level 3), the spot itself: its aim folds into the light, which needs no box.
    return affine_node(aimed_affine(at, kStageCentre - at),
                       splits == 0 ? spot : instance_node(fixture));
  };
  for (int qj = 0; qj < 2; ++qj) {
    for (int qi = 0; qi < 2; ++qi) {
      std::vector<SceneNode> blocks;
      for (int bj = 2 * qj; bj < 2 * qj + 2; ++bj) {
        for (int bi = 2 * qi; bi < 2 * qi + 2; ++bi) {
          std::vector<SceneNode> spots;
          for (int j = 2 * bj; j < 2 * bj + 2; ++j) {
            for (int i = 2 * bi; i < 2 * bi + 2; ++i) spots.push_back(fixture_at(i, j));
          }
          const std::string block = "rig_block_" + std::to_string(bi) + "_" + std::to_string(bj);
          blocks.push_back(instance_node(add_master(scene, block, union_node(std::move(spots)))));
        }
      }
      const std::string quadrant = "rig_quadrant_" + std::to_string(qi) + "_" + std::to_string(qj);
      parts.push_back(instance_node(add_master(scene, quadrant, union_node(std::move(blocks)))));
    }
  }
  scene.root = union_node(std::move(parts));

  // From the audience, the stage and the rig above it (thesis fig. 5.3).
  scene.camera.position = {0.0f, -13.0f, 4.5f};
  scene.camera.target = {0.0f, 5.0f, 4.0f};
  scene.camera.up = {0.0f, 0.0f, 1.0f};
  scene.camera.vertical_fov_deg = 55.0f;
  return scene;
}

renderer::Scene build_hall(int level) {
  return instantiate_scene(describe_hall(level));
}

}  // namespace scenes
