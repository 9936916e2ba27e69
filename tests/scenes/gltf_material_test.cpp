// glTF materials (scenes/gltf_scene.h, mapping in scenes/README.md): the base colour factor and
// the base colour texture, decoded with stb_image and sampled at the hit's uv with the sampler's
// wrap modes; metallic and roughness onto Phong; undecodable images fail with one line.
#include <stdexcept>
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

// The unit square at z = 0 facing +Z, uv = (x, y); a material of `material`; a sun shining down
// -Z with irradiance 1; the default camera (the node frame's -Z) from (0.5, 0.5, 2).
GltfBuilder textured_square(const tinygltf::Material& material) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  std::vector<float> uv = {0, 0, 1, 0, 1, 1, 0, 1};
  const int uvs = builder.add_accessor(builder.add_view(uv), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                       TINYGLTF_TYPE_VEC2, 4);
  const int indices =
      builder.add_accessor(builder.add_view(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
  builder.model.materials.push_back(material);
  tinygltf::Node square;
  square.mesh = builder.add_mesh({{"POSITION", positions}, {"TEXCOORD_0", uvs}}, indices,
                                 TINYGLTF_MODE_TRIANGLES, 0);
  builder.add_node(square);
  tinygltf::Light sun;
  sun.type = "directional";
  sun.intensity = 1.0;
  builder.add_node(GltfBuilder::light_node(builder.add_light(sun)));
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.perspective.yfov = 0.6;
  camera.perspective.znear = 0.1;
  builder.model.cameras.push_back(camera);
  tinygltf::Node eye;
  eye.camera = 0;
  eye.translation = {0.5, 0.5, 2};
  builder.add_node(eye);
  return builder;
}

tinygltf::Material matte(std::vector<double> factor) {
  tinygltf::Material m;
  m.pbrMetallicRoughness.baseColorFactor = std::move(factor);
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 1.0;
  return m;
}

TEST(GltfMaterial, BaseColourTextureIsSampledAtTheHitsUv) {
  tinygltf::Material material = matte({1.0, 0.5, 1.0, 1.0});
  GltfBuilder builder = textured_square(material);
  // Row 0 (v = 0): red, green; row 1: blue, white.
  const int texture =
      builder.add_png_texture(2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255},
                              TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE, TINYGLTF_TEXTURE_WRAP_REPEAT);
  builder.model.materials[0].pbrMetallicRoughness.baseColorTexture.index = texture;
  const scenes::SceneDescription description = scenes::parse_gltf_scene(builder.text(), "tex.gltf");
  ASSERT_EQ(description.textures.size(), 1u);
  const renderer::Texture& decoded = description.textures[0];
  EXPECT_EQ(decoded.width, 2);
  EXPECT_EQ(decoded.texels.at(0), glm::vec3(1, 0, 0));
  EXPECT_EQ(decoded.texels.at(3), glm::vec3(1, 1, 1));
  EXPECT_EQ(decoded.wrap_u, renderer::TextureWrap::clamp_to_edge);
  EXPECT_EQ(decoded.wrap_v, renderer::TextureWrap::repeat);

  const renderer::Scene scene = scenes::instantiate_scene(description);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = rs.height = 48;
  rs.method = lev::Method::rt;
  rs.max_depth = 0;
  auto state = renderer::make_render_state(scene, rays, rs);
  ASSERT_TRUE(renderer::render_pass(*state));
  const renderer::Framebuffer& image = renderer::render_framebuffer(*state);
  // Near each texel's centre the pixel shows that texel times the factor (kd 1, irradiance 1).
  const glm::vec2 centres[] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}};
  const glm::vec3 expected[] = {{1, 0, 0}, {0, 0.5f, 0}, {0, 0, 1}, {1, 0.5f, 1}};
  int checked[4] = {0, 0, 0, 0};
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      renderer::SurfaceHit hit;
      if (!rays.intersect(
              renderer::primary_ray(scene.camera, rs.width, rs.height, x + 0.5f, y + 0.5f), hit))
        continue;
      EXPECT_NEAR(hit.uv.x, hit.position.x, 1e-4f);
      EXPECT_NEAR(hit.uv.y, hit.position.y, 1e-4f);
      const glm::vec3 pixel = image.radiance_sum[static_cast<std::size_t>(y * rs.width + x)];
      for (int t = 0; t < 4; ++t) {
        if (glm::length(hit.uv - centres[t]) > 0.04f) continue;
        ++checked[t];
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(pixel[c], expected[t][c], 0.1f) << t << " at " << x << " " << y;
      }
    }
  }
  for (int t = 0; t < 4; ++t) EXPECT_GT(checked[t], 2) << t;
}

TEST(GltfMaterial, MetallicAndRoughnessMapOntoPhongAsDocumented) {
  tinygltf::Material shiny = matte({0.2, 0.4, 0.6, 1.0});
  shiny.pbrMetallicRoughness.metallicFactor = 1.0;
  shiny.pbrMetallicRoughness.roughnessFactor = 0.0;
  GltfBuilder builder = textured_square(shiny);
  const renderer::Material m =
      scenes::parse_gltf_scene(builder.text(), "m.gltf").materials.at(0).material;
  EXPECT_EQ(m.colour, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_FLOAT_EQ(m.kd, 0.0f);  // 1 - metallic x (1 - roughness)
  EXPECT_FLOAT_EQ(m.ks, 1.0f);  // (1 - roughness) x (0.04 + 0.96 metallic)
  EXPECT_FLOAT_EQ(m.kr, 1.0f);  // metallic x (1 - roughness)^2
  EXPECT_FLOAT_EQ(m.shininess, 10000.0f);
  GltfBuilder matte_builder = textured_square(matte({1, 1, 1, 1}));
  const renderer::Material d =
      scenes::parse_gltf_scene(matte_builder.text(), "m.gltf").materials.at(0).material;
  EXPECT_FLOAT_EQ(d.kd, 1.0f);
  EXPECT_FLOAT_EQ(d.ks, 0.0f);
  EXPECT_FLOAT_EQ(d.kr, 0.0f);
}

TEST(GltfMaterial, AnImageThatDoesNotDecodeFailsWithOneLine) {
  GltfBuilder builder = textured_square(matte({1, 1, 1, 1}));
  const int texture = builder.add_png_texture(1, 1, {9, 9, 9}, TINYGLTF_TEXTURE_WRAP_REPEAT,
                                              TINYGLTF_TEXTURE_WRAP_REPEAT);
  builder.model.materials[0].pbrMetallicRoughness.baseColorTexture.index = texture;
  // Overwrite the PNG signature.
  const tinygltf::BufferView& view = builder.model.bufferViews.back();
  builder.model.buffers[0].data[view.byteOffset] = 'X';
  try {
    scenes::parse_gltf_scene(builder.text(), "bad.gltf");
    FAIL() << "a broken PNG was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("bad.gltf: images[0]: cannot decode: ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

}  // namespace
