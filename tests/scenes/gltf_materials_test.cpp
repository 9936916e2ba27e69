// glTF materials and cameras as authored (scenes/gltf_materials.h, renderer/ray_scene.h), each
// against a small file the test builds: emission seen directly and in a mirror (and lighting
// nothing), a single-sided back face not drawn (but casting its shadow) and a double-sided one
// lit, a MASK cut-out seen through and casting a cut-out shadow, an unlit surface showing its
// base colour, and an orthographic camera whose image of an object does not change with distance.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/gltf_builder.h"

namespace {

using levrt_test::GltfBuilder;

constexpr int kSize = 64;

tinygltf::Material matte_material(std::vector<double> factor, bool double_sided = true) {
  tinygltf::Material m;
  m.pbrMetallicRoughness.baseColorFactor = std::move(factor);
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 1.0;
  m.doubleSided = double_sided;
  return m;
}

// A square [x0, x0 + size] x [y0, y0 + size] at height z, uv = its (x, y) from 0 to 1, facing +Z
// (counter-clockwise seen from +Z) or -Z, drawn with material `material`.
void add_square(GltfBuilder& builder, float x0, float y0, float size, float z, bool facing_up,
                int material) {
  const int positions = builder.add_vec3s(
      {{x0, y0, z}, {x0 + size, y0, z}, {x0 + size, y0 + size, z}, {x0, y0 + size, z}});
  const int uvs = builder.add_accessor(builder.add_view(std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}),
                                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, 4);
  const std::vector<std::uint16_t> up = {0, 1, 2, 0, 2, 3}, down = {0, 2, 1, 0, 3, 2};
  const int indices =
      builder.add_accessor(builder.add_view(facing_up ? up : down),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
  tinygltf::Node node;
  node.mesh = builder.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", uvs}}, indices,
                               TINYGLTF_MODE_TRIANGLES, material);
  builder.add_node(node);
}

int add_material(GltfBuilder& builder, const tinygltf::Material& material) {
  builder.model.materials.push_back(material);
  return static_cast<int>(builder.model.materials.size() - 1);
}

// A camera at `position` looking along the node's -Z, turned by the quaternion (x, y, z, w).
void add_materials_camera(GltfBuilder& builder, const std::vector<double>& position,
                          const std::vector<double>& rotation = {},
                          double orthographic_ymag = 0.0) {
  tinygltf::Camera camera;
  if (orthographic_ymag > 0.0) {
    camera.type = "orthographic";
    camera.orthographic.xmag = orthographic_ymag;
    camera.orthographic.ymag = orthographic_ymag;
    camera.orthographic.znear = 0.0;
    camera.orthographic.zfar = 100.0;
  } else {
    camera.type = "perspective";
    camera.perspective.yfov = 0.8;
    camera.perspective.znear = 0.1;
  }
  builder.model.cameras.push_back(camera);
  tinygltf::Node eye;
  eye.camera = static_cast<int>(builder.model.cameras.size() - 1);
  eye.translation = position;
  eye.rotation = rotation;
  builder.add_node(eye);
}

// A sun of irradiance 1 shining along the node's -Z turned by `rotation`.
void add_sun(GltfBuilder& builder, const std::vector<double>& rotation = {}) {
  tinygltf::Light sun;
  sun.type = "directional";
  sun.intensity = 1.0;
  tinygltf::Node node = GltfBuilder::light_node(builder.add_light(sun));
  node.rotation = rotation;
  builder.add_node(node);
}

// The quaternion turning -Z to +Z (half a turn about Y).
const std::vector<double> kFacingUp = {0.0, 1.0, 0.0, 0.0};

// The file rendered by rt, and what each camera ray of a pixel hits.
struct MaterialRender {
  renderer::Scene scene;
  std::unique_ptr<renderer::RayScene> rays;
  renderer::Framebuffer image;

  glm::vec3 pixel(int x, int y) const {
    return image.radiance_sum[static_cast<std::size_t>(y * kSize + x)];
  }
  bool hit(int x, int y, renderer::SurfaceHit& out) const {
    return rays->intersect(renderer::primary_ray(scene.camera, kSize, kSize, x + 0.5f, y + 0.5f),
                           out, true);
  }
};

std::unique_ptr<MaterialRender> render_materials(GltfBuilder& builder, int max_depth = 0) {
  auto r = std::make_unique<MaterialRender>();
  r->scene = scenes::instantiate_scene(scenes::parse_gltf_scene(builder.text(), "m.gltf"));
  r->rays = std::make_unique<renderer::RayScene>(r->scene);
  renderer::RenderSettings rs;
  rs.width = rs.height = kSize;
  rs.method = lev::Method::rt;
  rs.max_depth = max_depth;
  auto state = renderer::make_render_state(r->scene, *r->rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  r->image = renderer::render_framebuffer(*state);
  return r;
}

void expect_channels_near(const glm::vec3& got, const glm::vec3& want, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-4f) << what << " channel " << c;
}

tinygltf::Material emissive() {
  tinygltf::Material m = matte_material({0.0, 0.0, 0.0, 1.0});
  m.emissiveFactor = {1.0, 0.5, 0.25};
  tinygltf::Value::Object strength;
  strength["emissiveStrength"] = tinygltf::Value(2.0);
  m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strength);
  return m;
}

TEST(GltfMaterials, EmissionIsSeenDirectlyAndInAMirrorAndLightsNothing) {
  // No lights at all: the emissive square shows its emission, the white one beside it nothing.
  GltfBuilder direct;
  direct.model.extensionsUsed.push_back("KHR_materials_emissive_strength");
  add_square(direct, 0, 0, 1, 0, true, add_material(direct, emissive()));
  add_square(direct, 1.05f, 0, 1, 0, true, add_material(direct, matte_material({1, 1, 1, 1})));
  add_materials_camera(direct, {1.0, 0.5, 3.0});
  const auto seen = render_materials(direct);
  EXPECT_EQ(seen->scene.materials.at(0).emission, glm::vec3(2.0f, 1.0f, 0.5f));
  int emissive_pixels = 0, white_pixels = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      renderer::SurfaceHit hit;
      if (!seen->hit(x, y, hit)) continue;
      if (hit.position.x < 0.95f) {
        expect_channels_near(seen->pixel(x, y), {2.0f, 1.0f, 0.5f}, "the emissive square");
        ++emissive_pixels;
      } else if (hit.position.x > 1.1f) {
        expect_channels_near(seen->pixel(x, y), glm::vec3(0.0f), "the square beside it");
        ++white_pixels;
      }
    }
  }
  EXPECT_GT(emissive_pixels, 100);
  EXPECT_GT(white_pixels, 100);

  // A mirror below the camera, the emissive square above and behind it facing down: seen only
  // by the reflected rays.
  GltfBuilder mirrored;
  mirrored.model.extensionsUsed.push_back("KHR_materials_emissive_strength");
  tinygltf::Material mirror = matte_material({1, 1, 1, 1});
  mirror.pbrMetallicRoughness.metallicFactor = 1.0;
  mirror.pbrMetallicRoughness.roughnessFactor = 0.0;
  add_square(mirrored, -5, -5, 10, 0, true, add_material(mirrored, mirror));
  add_square(mirrored, -5, -5, 10, 3, false, add_material(mirrored, emissive()));
  add_materials_camera(mirrored, {0.0, 0.0, 2.0});
  const auto reflected = render_materials(mirrored, 1);
  const auto dark = render_materials(mirrored, 0);
  expect_channels_near(reflected->pixel(kSize / 2, kSize / 2), {2.0f, 1.0f, 0.5f}, "in the mirror");
  expect_channels_near(dark->pixel(kSize / 2, kSize / 2), glm::vec3(0.0f),
                       "no reflection at depth 0");
}

TEST(GltfMaterials, ABackFaceIsNotDrawnWhenSingleSidedAndLitWhenDoubleSided) {
  for (const bool double_sided : {false, true}) {
    // The square faces +Z; the camera and the sun are below it, on its back.
    GltfBuilder builder;
    add_square(builder, 0, 0, 1, 0, true,
               add_material(builder, matte_material({0.5, 0.5, 0.5, 1}, double_sided)));
    add_materials_camera(builder, {0.5, 0.5, -2.0}, kFacingUp);
    add_sun(builder, kFacingUp);
    const auto r = render_materials(builder);
    EXPECT_EQ(r->scene.materials.at(0).cull_back_faces, !double_sided);
    renderer::SurfaceHit hit;
    EXPECT_EQ(r->hit(kSize / 2, kSize / 2, hit), double_sided);
    expect_channels_near(r->pixel(kSize / 2, kSize / 2), glm::vec3(double_sided ? 0.5f : 0.0f),
                         double_sided ? "double-sided" : "single-sided");
    // From the front the single-sided square is drawn (and dark: the sun is behind it).
    GltfBuilder front = builder;
    front.model.nodes[1].translation = {0.5, 0.5, 2.0};
    front.model.nodes[1].rotation = {};
    EXPECT_TRUE(render_materials(front)->hit(kSize / 2, kSize / 2, hit));
  }
}

// A floor at z = 0 and above it at z = 1 the square [0, 1]^2 of `material` (facing up), lit by a
// sun shining down and toward +X at 45 degrees, so the square's shadow is the floor's [1, 2] x
// [0, 1]; seen from above. Per floor region under the sun's view of the square's left half (x in
// (1.1, 1.4)) and right half (x in (1.6, 1.9)), y in (0.1, 0.9): the largest and smallest radiance
// of the pixels seeing it; and how often camera rays meet the square's right half or pass it.
struct Shadow {
  float left_max = -1.0f, left_min = 1e9f, right_max = -1.0f, right_min = 1e9f;
  int left = 0, right = 0;
  int square_hits_right_half = 0, floor_under_right_half = 0;
};

Shadow shadow_of(const tinygltf::Material& material, GltfBuilder builder = GltfBuilder()) {
  add_square(builder, -3, -2, 6, 0, true, add_material(builder, matte_material({1, 1, 1, 1})));
  add_square(builder, 0, 0, 1, 1, true, add_material(builder, material));
  add_materials_camera(builder, {1.0, 0.5, 4.0});
  // -Z turned 45 degrees about -Y: the sun shines along (1, 0, -1) / sqrt(2).
  add_sun(builder, {0.0, -std::sin(M_PI / 8), 0.0, std::cos(M_PI / 8)});
  const auto r = render_materials(builder);
  Shadow s;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      renderer::SurfaceHit hit;
      if (!r->hit(x, y, hit) || hit.position.y < 0.1f || hit.position.y > 0.9f) continue;
      const float radiance = r->pixel(x, y).x;
      const float px = hit.position.x;
      if (hit.position.z > 0.5f && px > 0.6f && px < 0.9f) ++s.square_hits_right_half;
      if (hit.position.z > 0.5f) continue;
      if (px > 0.6f && px < 0.9f) ++s.floor_under_right_half;
      if (px > 1.1f && px < 1.4f) {
        s.left_max = std::max(s.left_max, radiance);
        s.left_min = std::min(s.left_min, radiance);
        ++s.left;
      } else if (px > 1.6f && px < 1.9f) {
        s.right_max = std::max(s.right_max, radiance);
        s.right_min = std::min(s.right_min, radiance);
        ++s.right;
      }
    }
  }
  EXPECT_GT(s.left, 10);
  EXPECT_GT(s.right, 10);
  return s;
}

TEST(GltfMaterials, ASingleSidedSurfaceCastsItsShadowFromBehindToo) {
  // The shadow rays from the floor meet the square's back face: it still blocks the sun.
  const Shadow s = shadow_of(matte_material({1, 1, 1, 1}, false));
  EXPECT_EQ(s.left_max, 0.0f);
  EXPECT_EQ(s.right_max, 0.0f);
}

TEST(GltfMaterials, AMaskCutOutIsSeenThroughAndCastsACutOutShadow) {
  // The square's texture: its left half opaque, its right half alpha 0 (clamped at the edges).
  GltfBuilder builder;
  const int texture = builder.add_png_texture(2, 1, {255, 255, 255, 255, 255, 255, 255, 0},
                                              TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE,
                                              TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE, 4);
  tinygltf::Material cut_out = matte_material({1, 1, 1, 1});
  cut_out.alphaMode = "MASK";
  cut_out.alphaCutoff = 0.5;
  cut_out.pbrMetallicRoughness.baseColorTexture.index = texture;
  const Shadow s = shadow_of(cut_out, builder);
  // The opaque half's shadow is dark; through the hole the sun lights the floor (cos 45).
  EXPECT_EQ(s.left_max, 0.0f);
  EXPECT_NEAR(s.right_min, std::cos(M_PI / 4), 1e-3);
  // Camera rays pass through the hole to the floor below it.
  EXPECT_EQ(s.square_hits_right_half, 0);
  EXPECT_GT(s.floor_under_right_half, 10);

  // The same square opaque: no hole, the whole shadow dark.
  tinygltf::Material opaque = cut_out;
  opaque.alphaMode = "OPAQUE";
  const Shadow o = shadow_of(opaque, builder);
  EXPECT_EQ(o.right_max, 0.0f);
  EXPECT_GT(o.square_hits_right_half, 10);
}

TEST(GltfMaterials, UnlitShowsTheBaseColourAsIs) {
  GltfBuilder builder;
  builder.model.extensionsUsed.push_back("KHR_materials_unlit");
  tinygltf::Material unlit = matte_material({0.2, 0.4, 0.6, 1});
  unlit.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
  add_square(builder, 0, 0, 1, 0, true, add_material(builder, unlit));
  add_materials_camera(builder, {0.5, 0.5, 2.0});
  // A sun at a grazing angle and one from behind: neither changes the colour.
  add_sun(builder, {0.0, std::sin(0.7), 0.0, std::cos(0.7)});
  add_sun(builder, kFacingUp);
  const auto r = render_materials(builder, 3);
  EXPECT_TRUE(r->scene.materials.at(0).unlit);
  expect_channels_near(r->pixel(kSize / 2, kSize / 2), {0.2f, 0.4f, 0.6f}, "unlit");
}

TEST(GltfMaterials, WhatIsNotRenderedIsNamedInOneWarningLinePerKind) {
  GltfBuilder builder;
  const int texture = builder.add_png_texture(1, 1, {255, 255, 255}, TINYGLTF_TEXTURE_WRAP_REPEAT,
                                              TINYGLTF_TEXTURE_WRAP_REPEAT);
  for (int i = 0; i < 2; ++i) {
    tinygltf::Material blend = matte_material({1, 1, 1, 0.5});
    blend.alphaMode = "BLEND";
    blend.normalTexture.index = texture;
    add_square(builder, 2.0f * static_cast<float>(i), 0, 1, 0, true, add_material(builder, blend));
  }
  testing::internal::CaptureStderr();
  (void)scenes::parse_gltf_scene(builder.text(), "w.gltf");
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warnings,
            "w.gltf: warning: materials: alphaMode BLEND (drawn opaque) not rendered (the first: "
            "materials[0])\n"
            "w.gltf: warning: materials: normalTexture not rendered (the first: materials[0])\n");
}

// The pixels whose camera ray hits the unit square seen from `distance` above it.
int square_pixels(double distance, double orthographic_ymag) {
  GltfBuilder builder;
  add_square(builder, 0, 0, 1, 0, true, add_material(builder, matte_material({1, 1, 1, 1})));
  add_materials_camera(builder, {0.5, 0.5, distance}, {}, orthographic_ymag);
  const renderer::Scene scene =
      scenes::instantiate_scene(scenes::parse_gltf_scene(builder.text(), "o.gltf"));
  EXPECT_EQ(scene.camera.orthographic_half_height, static_cast<float>(orthographic_ymag));
  const renderer::RayScene rays(scene);
  int pixels = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      renderer::SurfaceHit hit;
      pixels += rays.intersect(
          renderer::primary_ray(scene.camera, kSize, kSize, x + 0.5f, y + 0.5f), hit, true);
    }
  }
  return pixels;
}

TEST(GltfMaterials, AnOrthographicCameraSeesAnObjectAtTheSameSizeAtAnyDistance) {
  // ymag 1: the image is 2 units high, so the unit square covers half of it each way.
  EXPECT_EQ(square_pixels(2.0, 1.0), kSize * kSize / 4);
  EXPECT_EQ(square_pixels(20.0, 1.0), kSize * kSize / 4);
  EXPECT_EQ(square_pixels(2.0, 2.0), kSize * kSize / 16);
  // A perspective camera sees it shrink.
  EXPECT_GT(square_pixels(2.0, 0.0), 4 * square_pixels(20.0, 0.0));
}

}  // namespace
