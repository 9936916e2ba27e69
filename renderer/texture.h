// Colour textures (a glTF base colour texture) and their lookup at a hit's texture coordinates:
// bilinear between the four nearest texels, each texel index wrapped as the glTF sampler says
// (repeat, mirrored repeat, clamp to edge). Texels are kept as the file stores them (8-bit
// values / 255): levrt writes radiance to 8 bits without a transfer curve, so a texture shows
// as it was painted.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace renderer {

enum class TextureWrap : std::uint8_t { repeat, mirrored_repeat, clamp_to_edge };

struct Texture {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> texels;  // row-major, row 0 at v = 0 (glTF: the image's top row)
  TextureWrap wrap_u = TextureWrap::repeat;
  TextureWrap wrap_v = TextureWrap::repeat;
};

// The texel index i (any integer) maps to in [0, size) under wrap.
int wrap_texel_index(long long i, int size, TextureWrap wrap);

// The filtered colour at uv (texel centres at (i + 0.5) / width); black for an empty texture or
// a non-finite uv.
glm::vec3 sample_texture(const Texture& texture, const glm::vec2& uv);

}  // namespace renderer
