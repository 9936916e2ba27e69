// The viewer's heatmap colour scale: viridis over the rendered pixels' own range, min to max, on
// a log scale above the minimum, t = log(1 + v - min) / log(1 + max - min). Starting at the data's
// minimum rather than at 0 keeps a field like the hall's nodes visited (68 .. 172) from collapsing
// into one colour; the legend's ticks come from the inverse, so the picture and the legend agree.
// A constant field (min = max) is drawn at t = 0 and the legend states its value instead.
// The diverging map (signed fields: the difference against rt) runs blue through near-white to
// red, linear in t = value / half width, so equal and opposite values get colours equally far
// from white; the mask marks pixels in one red.
#pragma once

#include <cstdint>

#include "renderer/heatmap.h"

namespace app::viewer {

// In [0, 1]; 0 for a constant range and for values at or below min.
double heatmap_position(double value, const renderer::HeatmapRange& range);

// The value at position t in [0, 1] (the legend's ticks).
double heatmap_value_at(double t, const renderer::HeatmapRange& range);

// t in [-1, 1] (clamped): -1 blue, 0 near-white, 1 red.
glm::u8vec3 diverging_rgb8(double t);

// The mask view's colour of a pixel above the threshold.
extern const std::uint8_t kMaskRgb[3];

}  // namespace app::viewer
