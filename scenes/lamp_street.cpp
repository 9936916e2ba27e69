#include "scenes/lamp_street.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/generator_checks.h"
#include "scenes/scene_instantiation.h"
#include "scenes/seeded_random.h"

namespace scenes {
namespace {

const char* const kClassName = "lamp street";
constexpr float kRoadHalfWidth = 5.0f;
constexpr float kKerb = 5.5f;  // a lamp post's distance from the street's centre line
constexpr float kArm = 1.5f;   // the arm reaches over the road
constexpr float kHouseWidth = 6.0f, kHousePitch = 8.0f, kHouseDepth = 6.0f;

}  // namespace

std::uint64_t lamp_street_light_count(int level) {
  return 1ull << (2 * level);
}

LampStreetParams lamp_street_params(int level) {
  check_model_level("street", level, kLampStreetMinLevel, kLampStreetMaxLevel);

  LampStreetParams p;
  p.streets = 1 << (level - 2);
  p.lamps_per_side = 1 << (level + 1);
  return p;
}

SceneDescription describe_lamp_street_from(const LampStreetParams& p) {
  check_generator_parameter(p.streets >= 1, kClassName, "streets must be >= 1", p.streets);
  check_generator_parameter(p.lamps_per_side >= 1, kClassName, "lamps_per_side must be >= 1",
                            p.lamps_per_side);
  check_generator_parameter(p.lamp_spacing_m > 0.0f, kClassName, "lamp_spacing_m must be > 0",
                            p.lamp_spacing_m);
  check_generator_parameter(p.street_spacing_m > 2.0f * (kKerb + kHouseDepth), kClassName,
                            "street_spacing_m must leave room for houses", p.street_spacing_m);
  check_generator_parameter(p.lamp_height_m > 0.5f, kClassName, "lamp_height_m must be > 0.5",
                            p.lamp_height_m);
  check_generator_parameter(p.lamp_intensity > 0.0f, kClassName, "lamp_intensity must be > 0",
                            p.lamp_intensity);
  SceneDescription scene;
  scene.name = p.instanced ? "street" : "street_bare";
  scene.ambient = glm::vec3(0.3f);
  scene.background = glm::vec3(0.01f, 0.012f, 0.03f);
  const std::uint32_t ground = add_material(
      scene, "pavement", {{0.45f, 0.43f, 0.4f}, 0.1f, 0.7f, 0.05f, 10.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t asphalt = add_material(
      scene, "asphalt", {{0.2f, 0.2f, 0.22f}, 0.1f, 0.6f, 0.15f, 30.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t metal = add_material(
      scene, "lamp_metal", {{0.25f, 0.27f, 0.3f}, 0.1f, 0.4f, 0.5f, 40.0f, 0.0f, 0.0f, 1.0f});
  const std::uint32_t head = add_material(
      scene, "lamp_head", {{0.9f, 0.88f, 0.8f}, 1.0f, 0.3f, 0.3f, 20.0f, 0.0f, 0.0f, 1.0f});
  std::vector<std::uint32_t> walls;
  const glm::vec3 wall_colours[] = {
      {0.7f, 0.55f, 0.45f}, {0.6f, 0.62f, 0.58f}, {0.75f, 0.7f, 0.55f}, {0.5f, 0.35f, 0.3f}};
  for (int k = 0; k < 4; ++k) {
    walls.push_back(add_material(scene, "house_" + std::to_string(k),
                                 {wall_colours[k], 0.1f, 0.65f, 0.05f, 10.0f, 0.0f, 0.0f, 1.0f}));
  }

  // The lamp: a post at the kerb, an arm over the road (-y), a head and the light below it.
  const float h = p.lamp_height_m;
  const glm::vec3 light_at{0.0f, -kArm, h - 0.2f};
  std::vector<SceneNode> lamp_parts{
      cylinder_node(metal, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, h + 0.05f}, 0.09f, 10),
      cylinder_node(metal, {0.0f, 0.0f, h}, {0.0f, -kArm, h}, 0.05f, 8),
      box_node(head, {-0.25f, -kArm - 0.3f, h - 0.15f}, {0.25f, -kArm + 0.3f, h + 0.1f})};
  const SceneNode light = translate_node(
      light_at,
      spot_light_node(p.lamp_intensity * glm::vec3(1.0f, 0.86f, 0.62f), p.cone_degrees, p.dropoff));
  if (p.instanced) lamp_parts.push_back(light);
  const std::uint32_t lamp = add_master(scene, "lamp", union_node(std::move(lamp_parts)));

  const float length = p.lamp_spacing_m * static_cast<float>(p.lamps_per_side);
  const float width = p.street_spacing_m * static_cast<float>(p.streets);
  std::vector<SceneNode> parts;
  parts.push_back(quad_node(ground, {-10.0f, -0.5f * p.street_spacing_m, 0.0f},
                            {length + 20.0f, 0.0f, 0.0f}, {0.0f, width, 0.0f}));
  SeededRandom random(p.seed);
  for (int s = 0; s < p.streets; ++s) {
    const float y = p.street_spacing_m * static_cast<float>(s);
    parts.push_back(quad_node(asphalt, {-10.0f, y - kRoadHalfWidth, 0.01f},
                              {length + 20.0f, 0.0f, 0.0f}, {0.0f, 2.0f * kRoadHalfWidth, 0.0f}));
    for (int side = -1; side <= 1; side += 2) {
      for (int k = 0; k < p.lamps_per_side; ++k) {
        // Staggered sides; the south row turned to face the road.
        Affine a;
        a.translate = {p.lamp_spacing_m * (static_cast<float>(k) + (side > 0 ? 0.5f : 0.0f)),
                       y + static_cast<float>(side) * kKerb, 0.0f};
        if (side < 0) a.rotate_degrees = 180.0f;
        parts.push_back(affine_node(a, instance_node(lamp)));
        if (!p.instanced) parts.push_back(affine_node(a, light));
      }
      const float front = y + static_cast<float>(side) * (kKerb + 1.0f);
      for (float x = 0.0f; x + kHouseWidth <= length; x += kHousePitch) {
        const float height = random.uniform(4.0f, 12.0f);
        const auto colour = static_cast<std::size_t>(random.next() % walls.size());
        const float back = front + static_cast<float>(side) * kHouseDepth;
        parts.push_back(box_node(walls[colour], {x, std::min(front, back), 0.0f},
                                 {x + kHouseWidth, std::max(front, back), height}));
      }
    }
  }
  scene.root = union_node(std::move(parts));

  // Down the middle street from its end, at the height of a first floor.
  const float y_mid = p.street_spacing_m * static_cast<float>(p.streets / 2);
  scene.camera.position = {-6.0f, y_mid - 1.5f, 3.5f};
  scene.camera.target = {30.0f, y_mid, 1.5f};
  scene.camera.vertical_fov_deg = 50.0f;
  return scene;
}

SceneDescription describe_lamp_street(int level) {
  SceneDescription s = describe_lamp_street_from(lamp_street_params(level));
  s.level = level;
  return s;
}

SceneDescription describe_bare_lamp_street(int level) {
  LampStreetParams p = lamp_street_params(level);
  p.instanced = false;
  SceneDescription s = describe_lamp_street_from(p);
  s.level = level;
  return s;
}

renderer::Scene build_lamp_street(int level) {
  return instantiate_scene(describe_lamp_street(level));
}
renderer::Scene build_bare_lamp_street(int level) {
  return instantiate_scene(describe_bare_lamp_street(level));
}

}  // namespace scenes
