// A PNG read back as 8-bit RGB (stb_image), for tests that check what the viewer drew or a
// command wrote: empty (ok() false) when it cannot be read.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include <stb/stb_image.h>

namespace levrt_test {

struct PngImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  bool ok() const { return width > 0; }
  // The pixel at (x, y): R, G, B.
  const unsigned char* at(int x, int y) const {
    return &rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x))];
  }
};

inline PngImage read_png_image(const std::filesystem::path& path) {
  PngImage png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  if (!data) return {};
  png.rgb.assign(data, data + 3 * static_cast<std::size_t>(png.width) * png.height);
  stbi_image_free(data);
  return png;
}

}  // namespace levrt_test
