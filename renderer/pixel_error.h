// Pixel error against a reference image (thesis 5.4.2.4): per pixel |dR|+|dG|+|dB| on the
// 0..255 scale, as a percentage of 765.
#pragma once

#include <cstdint>
#include <vector>

namespace renderer {

struct PixelErrorStats {
  double average_pct = 0.0;
  double max_pct = 0.0;
};

// Per-pixel error in percent; both images 8-bit RGB of the same size.
std::vector<double> pixel_error_pct(const std::vector<std::uint8_t>& image,
                                    const std::vector<std::uint8_t>& reference);
PixelErrorStats summarize_pixel_error(const std::vector<double>& error_pct);

}  // namespace renderer
