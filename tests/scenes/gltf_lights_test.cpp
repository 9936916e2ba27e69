// glTF lights through the whole pipeline (scenes/gltf_scene.h): range and the smooth spot
// profile reach lev's lights, a range darkens the floor beyond it in every method, directional
// lights are shadow-tested suns outside the hierarchy, lev at tolerance 0 equals rt bit for bit
// on an imported scene with a sun, and --camera picks a perspective camera.
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/gltf_builder.h"
#include "tests/support/test_render.h"

namespace {

using levrt_test::GltfBuilder;

constexpr double kPi = 3.14159265358979323846;

// A 20 x 20 floor at y = 0 (glTF's up is +Y), facing up.
void add_floor(GltfBuilder& builder) {
  const int positions = builder.add_vec3s({{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}});
  const int normals = builder.add_vec3s({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}});
  const int indices =
      builder.add_accessor(builder.add_view(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
  tinygltf::Node floor;
  floor.mesh = builder.add_mesh({{"POSITION", positions}, {"NORMAL", normals}}, indices);
  builder.add_node(floor);
}

// A 2 x 2 roof at height 3 over the floor's centre.
void add_roof(GltfBuilder& builder) {
  const int positions = builder.add_vec3s({{-1, 3, 1}, {1, 3, 1}, {1, 3, -1}, {-1, 3, -1}});
  const int indices =
      builder.add_accessor(builder.add_view(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3}),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR, 6);
  tinygltf::Node roof;
  roof.mesh = builder.add_mesh({{"POSITION", positions}}, indices);
  builder.add_node(roof);
}

tinygltf::Light light_of(const std::string& type, std::vector<double> colour, double intensity,
                         double range = 0.0) {
  tinygltf::Light light;
  light.type = type;
  light.color = std::move(colour);
  light.intensity = intensity;
  light.range = range;
  return light;
}

// A node looking straight down (-Z turned onto -Y) from (x, height, z).
tinygltf::Node looking_down(double x, double height, double z) {
  tinygltf::Node node;
  node.translation = {x, height, z};
  node.rotation = {-std::sin(kPi / 4), 0, 0, std::cos(kPi / 4)};
  return node;
}

void add_light_node(GltfBuilder& builder, const tinygltf::Light& light, tinygltf::Node node) {
  tinygltf::Node with_light = GltfBuilder::light_node(builder.add_light(light));
  with_light.translation = node.translation;
  with_light.rotation = node.rotation;
  with_light.scale = node.scale;
  builder.add_node(with_light);
}

void add_lights_camera(GltfBuilder& builder, tinygltf::Node node, double yfov) {
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.perspective.yfov = yfov;
  camera.perspective.znear = 0.1;
  builder.model.cameras.push_back(camera);
  node.camera = static_cast<int>(builder.model.cameras.size() - 1);
  builder.add_node(node);
}

renderer::Framebuffer render_lights(const renderer::Scene& scene, lev::Method method,
                                    float tolerance, int size = 40) {
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs = test_render_settings(method, size, size);
  rs.tolerance = tolerance;
  rs.max_depth = 0;
  return render_test_image(scene, rays, rs);
}

scenes::SceneDescription parse_lights(GltfBuilder& builder, int camera = 0) {
  return scenes::parse_gltf_scene(builder.text(), "lights.gltf", camera);
}

// A floor, a roof, a grid of ranged point lights, two smooth spots, a sun from 45 degrees, and a
// camera looking down at the floor from height 12.
GltfBuilder street() {
  GltfBuilder builder;
  add_floor(builder);
  add_roof(builder);
  for (int i = 0; i < 6; ++i) {
    for (int k = 0; k < 6; ++k) {
      tinygltf::Node node;
      node.translation = {-7.5 + 3 * i, 1.0, -7.5 + 3 * k};
      add_light_node(builder, light_of("point", {0.2 * i, 0.5, 0.2 * k}, 2.0, 1.2), node);
    }
  }
  tinygltf::Light spot = light_of("spot", {1, 0.8, 0.6}, 30.0, 8.0);
  spot.spot.innerConeAngle = 0.2;
  spot.spot.outerConeAngle = 0.5;
  add_light_node(builder, spot, looking_down(4, 5, 4));
  spot.range = 0.0;
  add_light_node(builder, spot, looking_down(-4, 5, -4));
  // -Z turned onto (1, -1, 0) / sqrt(2): the roof's shadow falls on x in (2, 4), z in (-1, 1).
  tinygltf::Node sun;
  sun.rotation = {-0.5, -0.5, 0, std::sqrt(0.5)};
  add_light_node(builder, light_of("directional", {1, 1, 0.9}, 0.3), sun);
  add_lights_camera(builder, looking_down(0, 12, 0), 1.5);
  return builder;
}

TEST(GltfLights, RangeSmoothConesAndSunsReachTheRenderedScene) {
  GltfBuilder builder = street();
  const renderer::Scene scene = scenes::instantiate_scene(parse_lights(builder));
  const std::vector<lev::Light> lights = lev::flatten_lights(scene.lights);
  ASSERT_EQ(lights.size(), 38u);
  int ranged_points = 0, smooth_spots = 0;
  for (const lev::Light& light : lights) {
    if (light.kind == lev::LightKind::point) {
      ++ranged_points;
      EXPECT_FLOAT_EQ(light.range, 1.2f);
      EXPECT_FLOAT_EQ(light.intensity.y, 0.5f * 2.0f);  // colour x intensity, as authored
    } else {
      ++smooth_spots;
      EXPECT_EQ(light.profile, lev::SpotProfile::smooth);
      EXPECT_NEAR(light.cos_cone_half_angle, std::cos(0.5f), 1e-6f);
      EXPECT_NEAR(light.cos_inner_cone, std::cos(0.2f), 1e-6f);
      EXPECT_NEAR(light.direction.y, -1.0f, 1e-5f);
      // The range, or none (glTF's 0 or absent).
      EXPECT_TRUE(light.range == 8.0f || std::isinf(light.range)) << light.range;
    }
  }
  EXPECT_EQ(ranged_points, 36);
  EXPECT_EQ(smooth_spots, 2);
  ASSERT_EQ(scene.directional_lights.size(), 1u);
  EXPECT_NEAR(scene.directional_lights[0].direction.x, std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(scene.directional_lights[0].direction.y, -std::sqrt(0.5f), 1e-5f);
  // Lux as authored: colour x intensity.
  EXPECT_NEAR(scene.directional_lights[0].irradiance.x, 0.3f, 1e-6f);
  EXPECT_NEAR(scene.directional_lights[0].irradiance.z, 0.27f, 1e-6f);
}

TEST(GltfLights, LevAtToleranceZeroEqualsRtBitForBitWithASun) {
  GltfBuilder builder = street();
  const renderer::Scene scene = scenes::instantiate_scene(parse_lights(builder));
  const renderer::Framebuffer rt = render_lights(scene, lev::Method::rt, 0.0f);
  const renderer::Framebuffer lev = render_lights(scene, lev::Method::lev, 0.0f);
  EXPECT_TRUE(bitwise_equal(rt, lev));
  EXPECT_EQ(rt.shadow_rays, lev.shadow_rays);
  EXPECT_EQ(rt.lights_tested, lev.lights_tested);
  EXPECT_GT(renderer::sum_framebuffer(rt).shadow_rays,
            renderer::sum_framebuffer(rt).shading_points);
}

// Every pixel whose floor point lies beyond the range of every point light and outside both
// spots is lit by the sun alone, in every method: the ranges cut the irradiance to exactly zero.
// In the roof's shadow such a pixel is black (the scene's ambient is 0).
TEST(GltfLights, RangeAndSunShadowHoldInEveryMethod) {
  GltfBuilder builder = street();
  const renderer::Scene scene = scenes::instantiate_scene(parse_lights(builder));
  const renderer::RayScene rays(scene);
  const std::vector<lev::Light> lights = lev::flatten_lights(scene.lights);
  const int size = 72;
  const renderer::DirectionalLight sun = scene.directional_lights.at(0);
  for (const lev::Method method : {lev::Method::rt, lev::Method::ast, lev::Method::lev}) {
    const renderer::Framebuffer image = render_lights(scene, method, 0.001f, size);
    int sun_only = 0, shadowed = 0, lit = 0;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const renderer::Ray ray =
            renderer::primary_ray(scene.camera, size, size, x + 0.5f, y + 0.5f);
        renderer::SurfaceHit hit;
        if (!rays.intersect(ray, hit) || hit.position.y > 1.0f) continue;  // the floor only
        const glm::vec3 pixel = image.radiance_sum[static_cast<std::size_t>(y * size + x)];
        bool dark = true;
        for (const lev::Light& light : lights)
          dark = dark && lev::irradiance_falloff(light, hit.position) == 0.0f;
        if (!dark) {
          ++lit;
          continue;
        }
        // Where the ray towards the sun meets the roof's plane.
        const glm::vec3 roof =
            hit.position - sun.direction * ((3.0f - hit.position.y) / -sun.direction.y);
        const float margin = 0.05f;  // pixels on the shadow's edge are left out
        if (std::abs(roof.x) < 1.0f - margin && std::abs(roof.z) < 1.0f - margin) {
          ++shadowed;
          EXPECT_EQ(pixel, glm::vec3(0.0f)) << x << " " << y;
        } else if (std::abs(roof.x) > 1.0f + margin || std::abs(roof.z) > 1.0f + margin) {
          ++sun_only;
          // glTF's default material: white, kd 1 (scenes/README.md); the floor faces +Y.
          const glm::vec3 expected = sun.irradiance * -sun.direction.y;
          EXPECT_NEAR(pixel.x, expected.x, 1e-5f) << x << " " << y;
          EXPECT_NEAR(pixel.z, expected.z, 1e-5f) << x << " " << y;
        }
      }
    }
    EXPECT_GT(sun_only, 500) << lev::method_info(method).name;
    EXPECT_GT(shadowed, 10) << lev::method_info(method).name;
    EXPECT_GT(lit, 100) << lev::method_info(method).name;
  }
}

TEST(GltfLights, CameraIndexPicksACameraInNodeOrder) {
  GltfBuilder builder = street();
  add_lights_camera(builder, looking_down(3, 7, 0), 0.8);
  EXPECT_NEAR(parse_lights(builder, 0).camera.position.y, 12.0f, 1e-5f);
  const renderer::Camera second = parse_lights(builder, 1).camera;
  EXPECT_NEAR(second.position.x, 3.0f, 1e-5f);
  EXPECT_NEAR(second.vertical_fov_deg, 0.8 * 180.0 / kPi, 1e-3);
  try {
    parse_lights(builder, 2);
    FAIL() << "camera 2 of 2";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "lights.gltf: camera: 2 (the file has 2 cameras in its scene)");
  }
}

}  // namespace
