#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "renderer/heatmap.h"
#include "renderer/pixel_error.h"

namespace {

TEST(PixelError, ThesisDefinition) {
  const std::vector<std::uint8_t> a = {10, 20, 30, 0, 0, 0};
  const std::vector<std::uint8_t> b = {13, 18, 30, 255, 255, 255};
  const std::vector<double> e = renderer::pixel_error_pct(a, b);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_DOUBLE_EQ(e[0], 100.0 * 5.0 / 765.0);
  EXPECT_DOUBLE_EQ(e[1], 100.0);
  const auto s = renderer::summarize_pixel_error(e);
  EXPECT_DOUBLE_EQ(s.max_pct, 100.0);
  EXPECT_DOUBLE_EQ(s.average_pct, (e[0] + e[1]) / 2.0);
  EXPECT_THROW(renderer::pixel_error_pct(a, {1, 2, 3}), std::invalid_argument);
}

TEST(Heatmap, LogScaleAndViridisEnds) {
  EXPECT_EQ(renderer::viridis(0.0f), glm::u8vec3(68, 1, 84));
  EXPECT_EQ(renderer::viridis(1.0f), glm::u8vec3(253, 231, 37));
  renderer::HeatmapRange range;
  const auto rgb = renderer::heatmap_rgb8({0.0, 9.0, 99.0}, range);
  EXPECT_EQ(range.max, 99.0);
  EXPECT_EQ(rgb[0], 68);   // 0 -> bottom of the map
  EXPECT_EQ(rgb[6], 253);  // max -> top
  // log(10)/log(100) = 0.5: the middle of the map.
  EXPECT_EQ(glm::u8vec3(rgb[3], rgb[4], rgb[5]), renderer::viridis(0.5f));
}

}  // namespace
