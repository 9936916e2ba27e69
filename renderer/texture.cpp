#include "renderer/texture.h"

#include <cmath>

namespace renderer {

int wrap_texel_index(long long i, int size, TextureWrap wrap) {
  const long long n = size;
  switch (wrap) {
    case TextureWrap::clamp_to_edge:
      return static_cast<int>(i < 0 ? 0 : (i >= n ? n - 1 : i));
    case TextureWrap::mirrored_repeat: {
      const long long period = 2 * n;
      long long m = i % period;
      if (m < 0) m += period;
      return static_cast<int>(m < n ? m : period - 1 - m);
    }
    case TextureWrap::repeat:
    default: {
      long long m = i % n;
      if (m < 0) m += n;
      return static_cast<int>(m);
    }
  }
}

glm::vec3 sample_texture(const Texture& texture, const glm::vec2& uv) {
  if (texture.width <= 0 || texture.height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) {
    return glm::vec3(0.0f);
  }
  // Far outside [0, 1] only the fraction matters for repeat; the wrap handles the index, and
  // the clamp keeps the conversion to an integer defined.
  constexpr double kLimit = 1e9;
  const double x =
      std::fmin(std::fmax(static_cast<double>(uv.x) * texture.width - 0.5, -kLimit), kLimit);
  const double y =
      std::fmin(std::fmax(static_cast<double>(uv.y) * texture.height - 0.5, -kLimit), kLimit);
  const double x0 = std::floor(x), y0 = std::floor(y);
  const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const auto ix = static_cast<long long>(x0), iy = static_cast<long long>(y0);
  const auto texel = [&](long long i, long long j) {
    const int u = wrap_texel_index(i, texture.width, texture.wrap_u);
    const int v = wrap_texel_index(j, texture.height, texture.wrap_v);
    return texture.texels[static_cast<std::size_t>(v) * static_cast<std::size_t>(texture.width) +
                          static_cast<std::size_t>(u)];
  };
  const glm::vec3 top = (1.0f - fx) * texel(ix, iy) + fx * texel(ix + 1, iy);
  const glm::vec3 bottom = (1.0f - fx) * texel(ix, iy + 1) + fx * texel(ix + 1, iy + 1);
  return (1.0f - fy) * top + fy * bottom;
}

}  // namespace renderer
