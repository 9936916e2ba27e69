#include "app/viewer/heatmap_scale.h"

#include <algorithm>
#include <cmath>

namespace app::viewer {

double heatmap_position(double value, const renderer::HeatmapRange& range) {
  const double span = range.max - range.min;
  if (!(span > 0.0)) return 0.0;
  return std::clamp(std::log1p(std::max(value - range.min, 0.0)) / std::log1p(span), 0.0, 1.0);
}

double heatmap_value_at(double t, const renderer::HeatmapRange& range) {
  const double span = std::max(range.max - range.min, 0.0);
  return range.min + std::expm1(std::clamp(t, 0.0, 1.0) * std::log1p(span));
}

const std::uint8_t kMaskRgb[3] = {245, 40, 60};

glm::u8vec3 diverging_rgb8(double t) {
  const glm::vec3 white(235.0f, 235.0f, 235.0f);
  const glm::vec3 blue(40.0f, 90.0f, 220.0f);
  const glm::vec3 red(215.0f, 35.0f, 40.0f);
  const double clamped = std::isnan(t) ? 0.0 : std::clamp(t, -1.0, 1.0);
  const glm::vec3 end = clamped < 0.0 ? blue : red;
  const glm::vec3 c = glm::mix(white, end, static_cast<float>(std::abs(clamped)));
  return glm::u8vec3(glm::round(c));
}

}  // namespace app::viewer
