// The one table of views (app/view_table.h): every row is drawable by the viewer, has a legend,
// a hover read-out and a snapshot name, an unknown view fails loudly, and the headless heatmap
// outputs (flags, output paths, stats keys) are the table's rows with a flag.
#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "app/render_command.h"
#include "app/render_stats.h"
#include "app/view_table.h"
#include "app/viewer/display_image.h"
#include "renderer/framebuffer.h"
#include "tests/support/run_command.h"

namespace {

using app::ColourMap;
using app::ViewInfo;
using app::ViewMode;
using app::viewer::DisplayImage;
using app::viewer::ErrorImage;

// A 12 x 8 render of two passes with every per-pixel field varying, the missed-light estimate
// on, and a reference that differs from it in half the pixels (some brighter, some darker).
struct Fixture {
  DisplayImage image;
  DisplayImage reference;
  ErrorImage error;
};

renderer::Framebuffer framebuffer(float shade, bool missed, std::uint32_t samples) {
  renderer::Framebuffer f = renderer::make_framebuffer(12, 8);
  if (missed) renderer::allocate_missed_light(f);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    const float v = shade * static_cast<float>(i % 9) / 8.0f;
    const auto n = static_cast<float>(samples);
    f.samples[i] = samples;
    f.radiance_sum[i] = glm::vec3(v, 0.5f, 0.25f) * n;
    // Two samples mean -+ d per channel: a spread that varies from pixel to pixel.
    const glm::vec3 mean(v, 0.5f, 0.25f);
    const float d = 0.01f * static_cast<float>(i % 3);
    f.radiance_square_sum[i] = n * mean * mean + glm::vec3(n * d * d);
    f.shading_points[i] = 2 * samples;
    f.lights_tested[i] = (i % 5) * samples;
    f.nodes_visited[i] = (i % 7) * samples;
    f.error_bound_sum[i] = glm::vec3(0.01f * static_cast<float>(i % 4), 0.0f, 0.0f);
    if (missed) {
      f.missed_sum[i] = glm::vec3(0.02f * static_cast<float>(i % 6) * n, 0.0f, 0.0f);
      f.missed_variance_sum[i] = glm::vec3(0.0001f * static_cast<float>(i % 2));
    }
  }
  return f;
}

// Passes 0 and 1 of a render, each as one whole-frame tile.
std::vector<app::viewer::TileUpdate> two_passes(float shade, bool missed,
                                                std::uint64_t generation) {
  std::vector<app::viewer::TileUpdate> updates;
  for (std::uint32_t samples = 1; samples <= 2; ++samples) {
    const renderer::Framebuffer f = framebuffer(shade, missed, samples);
    updates.push_back(app::viewer::copy_tile(f, generation, 0, static_cast<int>(samples) - 1,
                                             {0, 0, f.width, f.height}));
  }
  return updates;
}

Fixture fixture() {
  Fixture x;
  app::viewer::apply_tile_updates(x.image, two_passes(0.9f, true, 3));
  app::viewer::apply_tile_updates(x.reference, two_passes(0.6f, false, 2));
  x.error = app::viewer::compute_error_image(x.image, x.reference, 1.0f);
  return x;
}

TEST(ViewTable, EveryModeHasExactlyOneRowAndAnUnknownModeFailsLoudly) {
  std::set<ViewMode> modes;
  for (const ViewInfo& view : app::view_table()) {
    EXPECT_TRUE(modes.insert(view.mode).second) << view.name;
    EXPECT_EQ(&app::view_info(view.mode), &view);
    EXPECT_EQ(app::parse_view_mode(view.name), view.mode);
  }
  EXPECT_EQ(modes.size(), static_cast<std::size_t>(ViewMode::mask) + 1);
  EXPECT_THROW(app::view_info(static_cast<ViewMode>(static_cast<int>(ViewMode::mask) + 1)),
               std::logic_error);
  EXPECT_FALSE(app::parse_view_mode("bogus").has_value());
}

TEST(ViewTable, EveryViewIsDrawnWithALegendAHoverReadOutAndASnapshotName) {
  const Fixture x = fixture();
  const app::ViewPixels pixels = app::viewer::view_pixels(x.image, x.error, 1.0);
  std::set<std::string> names, channels;
  for (const ViewInfo& view : app::view_table()) {
    SCOPED_TRACE(view.name);
    EXPECT_TRUE(names.insert(view.name).second);
    EXPECT_NE(std::string(view.label), "");
    // A snapshot file's suffix: plain lower-case letters.
    EXPECT_TRUE(std::all_of(view.name, view.name + std::string(view.name).size(),
                            [](char c) { return c >= 'a' && c <= 'z'; }));
    renderer::HeatmapRange range;
    const std::vector<std::uint8_t> rgb =
        app::viewer::view_rgb8(x.image, x.error, view.mode, range);
    ASSERT_EQ(rgb.size(), 3u * 12u * 8u);
    if (view.colour_map == ColourMap::image) {
      EXPECT_EQ(view.value, nullptr);
      continue;
    }
    EXPECT_NE(std::string(view.unit), "");  // the legend
    EXPECT_NE(std::string(view.zero), "");  // the legend of a field of zeros
    EXPECT_TRUE(channels.insert(view.channel).second);
    ASSERT_NE(view.value, nullptr);
    ASSERT_NE(view.hover, nullptr);
    // Every pixel has a value here, drawn in more than one colour (never the not-rendered grey).
    std::set<std::vector<std::uint8_t>> colours;
    for (std::size_t i = 0; i < pixels.count; ++i) {
      ASSERT_TRUE(view.value(pixels, i).has_value()) << i;
      EXPECT_NE(view.hover(pixels, i), "");
      const std::vector<std::uint8_t> c(rgb.begin() + 3 * i, rgb.begin() + 3 * i + 3);
      EXPECT_NE(c, std::vector<std::uint8_t>(app::viewer::kNotRenderedRgb,
                                             app::viewer::kNotRenderedRgb + 3));
      colours.insert(c);
    }
    EXPECT_GT(colours.size(), 1u);
    // Without the fields it reads, no value, and the read-out says why.
    app::ViewPixels empty = pixels;
    empty.error_pct = {};
    empty.difference_pct = {};
    empty.missed_pct = {};
    std::vector<std::uint32_t> unrendered(pixels.count, 0);
    empty.samples = unrendered.data();
    EXPECT_FALSE(view.value(empty, 0).has_value());
    EXPECT_NE(view.hover(empty, 0), "");
  }
}

TEST(ViewTable, TheDifferenceIsSignedAndTheMaskFollowsTheThreshold) {
  const Fixture x = fixture();
  const app::ViewPixels pixels = app::viewer::view_pixels(x.image, x.error, 1.0);
  const ViewInfo& difference = app::view_info(ViewMode::difference);
  const ViewInfo& mask = app::view_info(ViewMode::mask);
  bool positive = false, zero = false;
  for (std::size_t i = 0; i < pixels.count; ++i) {
    const double d = *difference.value(pixels, i);
    // |signed sum| <= the sum of the absolute differences.
    EXPECT_LE(std::abs(d), x.error.pct[i] + 1e-4);
    positive = positive || d > 0.0;
    zero = zero || (d == 0.0 && x.error.pct[i] == 0.0f);
    EXPECT_EQ(*mask.value(pixels, i), x.error.pct[i] > 1.0f ? 1.0 : 0.0);
  }
  EXPECT_TRUE(positive);  // the image is brighter than the reference where i % 9 > 0
  EXPECT_TRUE(zero);      // and equal where i % 9 == 0
  renderer::HeatmapRange range;
  app::viewer::view_rgb8(x.image, x.error, ViewMode::difference, range);
  EXPECT_EQ(range.min, -difference.fixed_range);
  EXPECT_EQ(range.max, difference.fixed_range);
  // A threshold above every error marks nothing.
  const app::ViewPixels high = app::viewer::view_pixels(x.image, x.error, 1000.0);
  for (std::size_t i = 0; i < high.count; ++i) EXPECT_EQ(*mask.value(high, i), 0.0);
}

TEST(ViewTable, TheHeadlessHeatmapOutputsAreTheRowsWithAFlag) {
  std::vector<std::string> flags;
  for (const ViewInfo& view : app::view_table()) {
    if (*view.output_flag != '\0') flags.push_back(view.output_flag);
  }
  EXPECT_GE(flags.size(), 6u);
  // The output paths checked before a render: --out, --stats, one per row, --reference-out.
  std::vector<std::string> listed;
  for (const app::OutputPath& p : app::render_output_paths(app::RenderOutputs{})) {
    if (p.flag.rfind("--heatmap-", 0) == 0) listed.push_back(p.flag);
  }
  EXPECT_EQ(listed, flags);
  // `levrt render --help` offers every flag.
  const levrt_test::CommandRun help = levrt_test::run_levrt({"render", "--help"});
  for (const std::string& flag : flags) EXPECT_NE(help.output.find(flag), std::string::npos);
  // The stats name each heatmap's range after its view.
  app::RenderStats stats;
  for (const ViewInfo& view : app::view_table()) stats.heatmap_ranges[view.mode] = {1.0, 2.0};
  const nlohmann::ordered_json json = app::render_stats_json(stats);
  for (const ViewInfo& view : app::view_table()) {
    EXPECT_TRUE(json.contains(std::string("heatmap_") + view.name + "_range")) << view.name;
  }
}

}  // namespace
