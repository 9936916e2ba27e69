// Texture lookups (renderer/texture.h): texel centres return their texel exactly, bilinear
// between them, and the three glTF wrap modes map any texel index as the spec says.
#include "renderer/texture.h"

#include <gtest/gtest.h>

namespace {

// 2 x 2: red, green / blue, white.
renderer::Texture checker(renderer::TextureWrap wrap) {
  renderer::Texture t;
  t.width = 2;
  t.height = 2;
  t.texels = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  t.wrap_u = t.wrap_v = wrap;
  return t;
}

TEST(Texture, TexelCentresAndBilinearBetweenThem) {
  const renderer::Texture t = checker(renderer::TextureWrap::clamp_to_edge);
  EXPECT_EQ(renderer::sample_texture(t, {0.25f, 0.25f}), glm::vec3(1, 0, 0));
  EXPECT_EQ(renderer::sample_texture(t, {0.75f, 0.25f}), glm::vec3(0, 1, 0));
  EXPECT_EQ(renderer::sample_texture(t, {0.25f, 0.75f}), glm::vec3(0, 0, 1));
  EXPECT_EQ(renderer::sample_texture(t, {0.75f, 0.75f}), glm::vec3(1, 1, 1));
  const glm::vec3 middle = renderer::sample_texture(t, {0.5f, 0.5f});
  EXPECT_NEAR(middle.x, 0.5f, 1e-6f);
  EXPECT_NEAR(middle.y, 0.5f, 1e-6f);
  EXPECT_NEAR(middle.z, 0.5f, 1e-6f);
  // Clamped: far outside, the edge texel.
  EXPECT_EQ(renderer::sample_texture(t, {-7.0f, 0.25f}), glm::vec3(1, 0, 0));
  EXPECT_EQ(renderer::sample_texture(t, {9.0f, 9.0f}), glm::vec3(1, 1, 1));
  EXPECT_EQ(renderer::sample_texture(renderer::Texture{}, {0.5f, 0.5f}), glm::vec3(0.0f));
}

TEST(Texture, WrapModesFollowTheSpec) {
  using renderer::TextureWrap;
  // From index -2 (clamp: -1, mirrored: -3) on: repeat is i mod n; mirrored runs 2 1 0 | 0 1 2 | 2;
  // clamp keeps the edge.
  const int repeat[] = {1, 2, 0, 1, 2, 0, 1};
  const int mirrored[] = {2, 1, 0, 0, 1, 2, 2};
  const int clamped[] = {0, 0, 1, 2, 2, 2, 2};
  for (int k = 0; k < 7; ++k) {
    const long long i = k - 2;
    const long long mirrored_i = k - 3;
    EXPECT_EQ(renderer::wrap_texel_index(i, 3, TextureWrap::repeat), repeat[k]) << i;
    EXPECT_EQ(renderer::wrap_texel_index(mirrored_i, 3, TextureWrap::mirrored_repeat), mirrored[k])
        << mirrored_i;
    EXPECT_EQ(renderer::wrap_texel_index(i + 1, 3, TextureWrap::clamp_to_edge), clamped[k])
        << i + 1;
  }
  // uv 1.25 repeats to 0.25, mirrors to 0.75.
  EXPECT_EQ(renderer::sample_texture(checker(TextureWrap::repeat), {1.25f, 0.25f}),
            glm::vec3(1, 0, 0));
  EXPECT_EQ(renderer::sample_texture(checker(TextureWrap::mirrored_repeat), {1.25f, 0.25f}),
            glm::vec3(0, 1, 0));
}

}  // namespace
