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

// Maps values >= 0 to colours with t = log(1 + v) / log(1 + range.max). The range is the data's
// min and max unless given (the viewer pins a range to compare frames).
std::vector<std::uint8_t> heatmap_rgb8(const std::vector<double>& values, HeatmapRange& range,
                                       bool use_given_range = false);

}  // namespace renderer
