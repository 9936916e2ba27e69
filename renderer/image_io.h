// PNG output that never leaves a half-written file: the image goes to a temporary name in the
// same folder and is renamed over the target only when complete.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace renderer {

// Throws std::runtime_error naming the path on failure.
void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);
// Same guarantee for text (stats JSON).
void write_text_file(const std::string& path, const std::string& text);

}  // namespace renderer
