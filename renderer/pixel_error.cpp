#include "renderer/pixel_error.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace renderer {

std::vector<double> pixel_error_pct(const std::vector<std::uint8_t>& image,
                                    const std::vector<std::uint8_t>& reference) {
  if (image.size() != reference.size() || image.size() % 3 != 0) {
    throw std::invalid_argument("pixel error: images differ in size");
  }
  std::vector<double> error(image.size() / 3);
  for (std::size_t i = 0; i < error.size(); ++i) {
    int sum = 0;
    for (int c = 0; c < 3; ++c) sum += std::abs(int{image[3 * i + c]} - int{reference[3 * i + c]});
    error[i] = 100.0 * sum / 765.0;
  }
  return error;
}

PixelErrorStats summarize_pixel_error(const std::vector<double>& error_pct) {
  PixelErrorStats s;
  if (error_pct.empty()) return s;
  double sum = 0.0;
  for (double e : error_pct) {
    sum += e;
    s.max_pct = std::max(s.max_pct, e);
  }
  s.average_pct = sum / static_cast<double>(error_pct.size());
  return s;
}

}  // namespace renderer
