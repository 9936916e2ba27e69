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

}  // namespace app::viewer
