#include "renderer/heatmap.h"

#include <algorithm>
#include <cmath>

namespace renderer {

glm::u8vec3 viridis(float t) {
  // Nine samples of matplotlib's viridis at t = 0, 1/8, ..., 1; linear in between.
  static const glm::vec3 kStops[9] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                      {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                      {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  const float x = std::clamp(std::isnan(t) ? 0.0f : t, 0.0f, 1.0f) * 8.0f;
  const int i = std::min(static_cast<int>(x), 7);
  const glm::vec3 c = glm::mix(kStops[i], kStops[i + 1], x - static_cast<float>(i));
  return glm::u8vec3(glm::round(c));
}

std::vector<std::uint8_t> heatmap_rgb8(const std::vector<double>& values, HeatmapRange& range,
                                       bool use_given_range) {
  if (!use_given_range) {
    range = {};
    if (!values.empty()) {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      range = {*lo, *hi};
    }
  }
  const double denominator = std::log1p(std::max(range.max, 0.0));
  std::vector<std::uint8_t> rgb(values.size() * 3);
  for (std::size_t i = 0; i < values.size(); ++i) {
    double t = denominator > 0.0 ? std::log1p(std::max(values[i], 0.0)) / denominator : 0.0;
    if (use_given_range) t = heatmap_position(values[i], range);
    const glm::u8vec3 c = viridis(static_cast<float>(t));
    rgb[3 * i] = c.x;
    rgb[3 * i + 1] = c.y;
    rgb[3 * i + 2] = c.z;
  }
  return rgb;
}

double heatmap_position(double value, const HeatmapRange& range) {
  const double span = range.max - range.min;
  if (!(span > 0.0)) return 0.0;
  return std::clamp(std::log1p(std::max(value - range.min, 0.0)) / std::log1p(span), 0.0, 1.0);
}

double heatmap_value_at(double t, const HeatmapRange& range) {
  const double span = std::max(range.max - range.min, 0.0);
  return range.min + std::expm1(std::clamp(t, 0.0, 1.0) * std::log1p(span));
}

}  // namespace renderer
