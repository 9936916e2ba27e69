// The viewer's heatmap colour scale: viridis over the rendered pixels' own range, min to max, on
// a log scale above the minimum, t = log(1 + v - min) / log(1 + max - min). Starting at the data's
// minimum rather than at 0 keeps a field like the hall's nodes visited (68 .. 172) from collapsing
// into one colour; the legend's ticks come from the inverse, so the picture and the legend agree.
// A constant field (min = max) is drawn at t = 0 and the legend states its value instead.
#pragma once

#include "renderer/heatmap.h"

namespace app::viewer {

// In [0, 1]; 0 for a constant range and for values at or below min.
double heatmap_position(double value, const renderer::HeatmapRange& range);

// The value at position t in [0, 1] (the legend's ticks).
double heatmap_value_at(double t, const renderer::HeatmapRange& range);

}  // namespace app::viewer
