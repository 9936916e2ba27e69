// Heatmaps of per-pixel work (lights tested, nodes visited, pixel error) in the viridis colour
// map on a log scale, so that 1 and 10,000 tests per pixel are both readable.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace renderer {

// Viridis at t in [0, 1] (clamped), as 8-bit RGB.
glm::u8vec3 viridis(float t);

struct HeatmapRange {
  double min = 0.0;
  double max = 0.0;
};

// Maps values >= 0 to colours with t = log(1 + v) / log(1 + range.max), range the data's min and
// max. With a given range (`--heatmap-range`, the viewer's range lock: two renders compared on
// one scale) the scale is the viewer's, from the given minimum: heatmap_position.
std::vector<std::uint8_t> heatmap_rgb8(const std::vector<double>& values, HeatmapRange& range,
                                       bool use_given_range = false);

// In [0, 1]: t = log(1 + v - min) / log(1 + max - min), clamped; 0 for a constant range and for
// values at or below min.
double heatmap_position(double value, const HeatmapRange& range);

// The value at position t in [0, 1] (a legend's ticks).
double heatmap_value_at(double t, const HeatmapRange& range);

}  // namespace renderer
