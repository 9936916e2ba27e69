// The viewer's heatmap scale and the heatmap views built on it: colours span the rendered
// pixels' min .. max (a field of 68 .. 172 uses the whole colour map, not its top third), the
// legend's tick values are the scale's inverse, and a constant field is one colour whose range
// says its value.
#include <vector>

#include <gtest/gtest.h>

#include "app/viewer/display_image.h"
#include "app/viewer/heatmap_scale.h"
#include "renderer/heatmap.h"

namespace {

using app::viewer::heatmap_position;
using app::viewer::heatmap_value_at;

TEST(HeatmapScale, SpansTheRangeFromItsMinimumAndInvertsForTheLegend) {
  const renderer::HeatmapRange range{68.0, 172.0};
  EXPECT_EQ(heatmap_position(68.0, range), 0.0);
  EXPECT_DOUBLE_EQ(heatmap_position(172.0, range), 1.0);
  double previous = -1.0;
  for (double v = 68.0; v <= 172.0; v += 4.0) {
    const double t = heatmap_position(v, range);
    EXPECT_GT(t, previous) << v;
    EXPECT_NEAR(heatmap_value_at(t, range), v, 1e-9) << v;
    previous = t;
  }
  EXPECT_DOUBLE_EQ(heatmap_value_at(0.0, range), 68.0);
  EXPECT_DOUBLE_EQ(heatmap_value_at(1.0, range), 172.0);
  // Outside the range: clamped to the ends.
  EXPECT_EQ(heatmap_position(10.0, range), 0.0);
  EXPECT_EQ(heatmap_position(1000.0, range), 1.0);
}

TEST(HeatmapScale, AConstantRangeIsPositionZeroAndItsValue) {
  const renderer::HeatmapRange range{5.0, 5.0};
  EXPECT_EQ(heatmap_position(5.0, range), 0.0);
  EXPECT_EQ(heatmap_value_at(0.5, range), 5.0);
  const renderer::HeatmapRange zeros{0.0, 0.0};
  EXPECT_EQ(heatmap_position(0.0, zeros), 0.0);
}

// A 4x1 error view with the given per-pixel values (negative: not compared yet).
std::vector<std::uint8_t> error_view(const std::vector<float>& pct, renderer::HeatmapRange& range) {
  app::viewer::DisplayImage image;
  image.width = static_cast<int>(pct.size());
  image.height = 1;
  app::viewer::ErrorImage error;
  error.pct = pct;
  return app::viewer::view_rgb8(image, error, app::ViewMode::error, range);
}

glm::u8vec3 pixel(const std::vector<std::uint8_t>& rgb, int i) {
  return {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
}

TEST(HeatmapView, ColoursSpanTheRenderedPixelsMinToMax) {
  renderer::HeatmapRange range;
  const std::vector<std::uint8_t> rgb = error_view({68.0f, 100.0f, 172.0f, -1.0f}, range);
  EXPECT_EQ(range.min, 68.0);
  EXPECT_EQ(range.max, 172.0);
  EXPECT_EQ(pixel(rgb, 0), renderer::viridis(0.0f));
  EXPECT_EQ(pixel(rgb, 2), renderer::viridis(1.0f));
  EXPECT_NE(pixel(rgb, 1), pixel(rgb, 0));
  EXPECT_NE(pixel(rgb, 1), pixel(rgb, 2));
  // The pixel not compared yet keeps the not-rendered grey, not a colour of the map's ends.
  EXPECT_NE(pixel(rgb, 3), renderer::viridis(0.0f));
  EXPECT_NE(pixel(rgb, 3), renderer::viridis(1.0f));
}

TEST(HeatmapView, AConstantFieldIsOneColourAndItsRangeNamesTheValue) {
  renderer::HeatmapRange range;
  const std::vector<std::uint8_t> rgb = error_view({68.0f, 68.0f, 68.0f, 68.0f}, range);
  EXPECT_EQ(range.min, 68.0);
  EXPECT_EQ(range.max, 68.0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel(rgb, i), renderer::viridis(0.0f)) << i;
}

}  // namespace
