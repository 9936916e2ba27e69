#include "scenes/stage_rig.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/generator_checks.h"
#include "scenes/scene_instantiation.h"
#include "scenes/seeded_random.h"

namespace scenes {
namespace {

const char* const kClassName = "stage rig";
constexpr float kStageHeight = 1.0f;
const glm::vec3 kStageCentre{0.0f, 4.0f, kStageHeight};

// A saturated colour of the given hue (0..1), brightest channel 1.
glm::vec3 hue_colour(float hue) {
  const float h = 6.0f * hue;
  const glm::vec3 rgb{std::abs(h - 3.0f) - 1.0f, 2.0f - std::abs(h - 2.0f),
                      2.0f - std::abs(h - 4.0f)};
  return glm::mix(glm::vec3(1.0f), glm::clamp(rgb, 0.0f, 1.0f), 0.8f);
}

}  // namespace

std::uint64_t stage_rig_light_count(int level) {
  return 72ull << (2 * (level - 3));
}

StageRigParams stage_rig_params(int level) {
  check_model_level("stage", level, kStageRigMinLevel, kStageRigMaxLevel);

  StageRigParams p;
  p.spots = static_cast<int>(stage_rig_light_count(level));
  return p;
}

SceneDescription describe_stage_rig_from(const StageRigParams& p) {
  check_generator_parameter(p.spots >= 1, kClassName, "spots must be >= 1", p.spots);
  check_generator_parameter(p.truss_width_m > 0.0f && p.truss_depth_m > 0.0f, kClassName,
                            "truss sizes must be > 0", p.truss_width_m);
  check_generator_parameter(p.truss_height_m > kStageHeight + 1.0f, kClassName,
                            "truss_height_m must clear the stage", p.truss_height_m);
  check_generator_parameter(p.aim_radius_m >= 0.0f, kClassName, "aim_radius_m must be >= 0",
                            p.aim_radius_m);
  check_generator_parameter(p.cone_min_degrees > 0.0f && p.cone_min_degrees <= p.cone_max_degrees &&
                                p.cone_max_degrees <= 90.0f,
                            kClassName, "cones must satisfy 0 < min <= max <= 90",
                            p.cone_min_degrees);
  check_generator_parameter(p.dropoff_min >= 0.0f && p.dropoff_min <= p.dropoff_max, kClassName,
                            "dropoffs must satisfy 0 <= min <= max", p.dropoff_min);
  check_generator_parameter(p.total_intensity > 0.0f, kClassName, "total_intensity must be > 0",
                            p.total_intensity);
  SceneDescription scene;
  scene.name = "stage";
  scene.ambient = glm::vec3(0.2f);
  const std::uint32_t floor = add_material(
      scene, "floor", {{0.25f, 0.25f, 0.28f}, 0.1f, 0.5f, 0.05f, 10.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t boards = add_material(
      scene, "stage", {{0.6f, 0.45f, 0.3f}, 0.1f, 0.6f, 0.2f, 25.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t drape = add_material(
      scene, "backdrop", {{0.3f, 0.08f, 0.1f}, 0.1f, 0.55f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t mirror = add_material(
      scene, "mirror", {{0.9f, 0.9f, 0.95f}, 0.02f, 0.05f, 0.4f, 200.0f, 0.85f, 0.0f, 1.0f});
  const std::uint32_t glass = add_material(
      scene, "glass", {{0.95f, 0.97f, 1.0f}, 0.0f, 0.02f, 0.5f, 150.0f, 0.08f, 0.9f, 1.5f});
  const std::uint32_t chrome = add_material(
      scene, "chrome", {{0.85f, 0.85f, 0.88f}, 0.05f, 0.1f, 0.6f, 90.0f, 0.5f, 0.0f, 1.0f});
  const std::uint32_t dancer = add_material(
      scene, "performer", {{0.8f, 0.78f, 0.75f}, 0.1f, 0.7f, 0.3f, 30.0f, 0.0f, 0.0f, 1.0f});

  std::vector<SceneNode> parts;
  parts.push_back(
      quad_node(floor, {-30.0f, -30.0f, 0.0f}, {60.0f, 0.0f, 0.0f}, {0.0f, 50.0f, 0.0f}));
  parts.push_back(box_node(boards, {-10.0f, -1.0f, 0.0f}, {10.0f, 10.0f, kStageHeight}));
  parts.push_back(
      quad_node(drape, {-16.0f, 11.0f, 0.0f}, {32.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 14.0f}));
  // A tall mirror turned towards the audience at stage left, a glass sphere and a glass column.
  parts.push_back(
      quad_node(mirror, {-8.5f, 6.0f, kStageHeight}, {4.0f, 2.5f, 0.0f}, {0.0f, 0.0f, 5.0f}));
  parts.push_back(sphere_node(glass, kStageCentre + glm::vec3(2.5f, -1.0f, 1.3f), 1.3f));
  parts.push_back(cylinder_node(glass, kStageCentre + glm::vec3(-2.0f, 2.0f, 0.0f),
                                kStageCentre + glm::vec3(-2.0f, 2.0f, 3.5f), 0.7f, 32));
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 at = kStageCentre + glm::vec3(-4.0f + 4.0f * static_cast<float>(k), 3.5f, 0.0f);
    parts.push_back(cylinder_node(dancer, at, at + glm::vec3(0.0f, 0.0f, 1.6f), 0.3f, 16));
    parts.push_back(sphere_node(chrome, at + glm::vec3(0.0f, 0.0f, 1.9f), 0.28f));
  }

  SeededRandom random(p.seed);
  const float intensity = p.total_intensity / static_cast<float>(p.spots);
  for (int k = 0; k < p.spots; ++k) {
    // Three in four on the truss over the stage, the rest on two towers at its sides.
    glm::vec3 at;
    if (k % 4 != 3) {
      at = {random.uniform(-0.5f, 0.5f) * p.truss_width_m,
            kStageCentre.y + random.uniform(-0.5f, 0.5f) * p.truss_depth_m, p.truss_height_m};
    } else {
      const float side = random.uniform(0.0f, 1.0f) < 0.5f ? -1.0f : 1.0f;
      at = {side * (0.5f * p.truss_width_m + 2.0f),
            kStageCentre.y + random.uniform(-0.5f, 0.5f) * p.truss_depth_m,
            random.uniform(kStageHeight + 2.0f, p.truss_height_m)};
    }
    const float angle = random.uniform(0.0f, 6.2831853f),
                radius = p.aim_radius_m * std::sqrt(random.uniform(0.0f, 1.0f));
    const glm::vec3 aim =
        kStageCentre + glm::vec3(radius * std::cos(angle), radius * std::sin(angle), 0.0f);
    const float cone = random.uniform(p.cone_min_degrees, p.cone_max_degrees);
    const float dropoff = random.uniform(p.dropoff_min, p.dropoff_max);
    parts.push_back(affine_node(
        aimed_affine(at, aim - at),
        spot_light_node(intensity * hue_colour(random.uniform(0.0f, 1.0f)), cone, dropoff)));
  }
  scene.root = union_node(std::move(parts));

  // From the audience, the whole stage and the mirror.
  scene.camera.position = {0.0f, -9.0f, 4.0f};
  scene.camera.target = {0.0f, 4.5f, 2.0f};
  scene.camera.vertical_fov_deg = 50.0f;
  return scene;
}

SceneDescription describe_stage_rig(int level) {
  SceneDescription s = describe_stage_rig_from(stage_rig_params(level));
  s.level = level;
  return s;
}

renderer::Scene build_stage_rig(int level) {
  return instantiate_scene(describe_stage_rig(level));
}

}  // namespace scenes
