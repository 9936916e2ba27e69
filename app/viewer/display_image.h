// The UI thread's own copy of a render: finished tiles taken from a DisplayBuffer are written
// into these per-pixel arrays, and everything the panel shows (texture, hover values, totals,
// pixel errors) is computed from them on the UI thread. When a new render starts at the same
// size, the previous colours stay as a dimmed backdrop until their tiles arrive again.
// Preview samples live in a PreviewImage of their own, which only the texture composition reads:
// snapshots, statistics, pixel errors and the trade plot are made from the DisplayImage, which
// never holds a preview sample.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "app/view_table.h"
#include "app/viewer/display_buffer.h"
#include "renderer/display_transform.h"
#include "renderer/heatmap.h"

namespace app::viewer {

struct DisplayImage {
  int width = 0;
  int height = 0;
  std::uint64_t generation = 0;
  // The exposure (2^EV) of rgb and of every figure in percent below: the render's when its first
  // tile arrives, then the one the UI shows (expose_display_image).
  float exposure_scale = 1.0f;
  std::vector<std::uint8_t> rgb;    // latest mean colour, exposed linear 8-bit
  std::vector<glm::vec3> radiance;  // latest mean scene-linear radiance (shown)
  // The mean radiance after 1, 2, 4, ... samples (level L: 2^L), kept so that an error against
  // a reference that is further along compares the same passes (compute_error_image).
  std::vector<std::vector<glm::vec3>> radiance_at_power_of_two;
  std::vector<std::uint32_t> samples;   // 0: not rendered yet in this generation
  std::vector<float> lights_tested;     // per sample
  std::vector<float> nodes_visited;     // per sample
  std::vector<float> noise_pct;         // estimated standard error; 0 below two samples
  std::vector<TileTotals> tile_totals;  // by tile index
  std::vector<std::uint8_t> tile_seen;  // by tile index
  int tiles_seen = 0;
  int pass = 0;                // the pass the latest tile belongs to
  int tiles_done_in_pass = 0;  // tiles of that pass received so far
  std::uint64_t version = 0;   // bumped whenever anything above changes
  // The certified bound of the error against rt per pixel, % of 765, of the mean colour (every
  // pass so far, as `levrt render` reports it).
  std::vector<float> error_bound_pct;
  // The missed-light estimate and its standard error, % of 765, where the render estimates it
  // (has_missed: some tile of this generation carried it).
  std::vector<float> missed_pct;
  std::vector<float> missed_std_error_pct;
  bool has_missed = false;
  // The same figures before the exposure (TileUpdate), from which the percentages are made.
  std::vector<double> std_error;
  std::vector<glm::vec3> error_bound_mean;
  std::vector<glm::vec3> missed_mean;
  std::vector<glm::vec3> missed_std_error;
};

// The coarse preview of the render in `generation`: per image pixel, the value of the preview
// sample whose block covers it (the finest level received so far).
struct PreviewImage {
  int width = 0;
  int height = 0;
  std::uint64_t generation = 0;
  std::vector<std::uint8_t> step;  // 0: no preview sample covers the pixel yet
  std::vector<std::uint8_t> rgb;
  std::vector<glm::vec3> radiance;
  std::vector<float> lights_tested;  // per sample
  std::vector<float> nodes_visited;
  std::vector<float> error_bound_pct;
};

// Forgets everything (no render to show).
void clear_display_image(DisplayImage& image);

// Applies updates of this generation, starts a newer one when an update belongs to it, and drops
// updates of older generations. Returns true when the image changed.
bool apply_tile_updates(DisplayImage& image, const std::vector<TileUpdate>& updates);

// Applies preview tiles (TileUpdate::preview_step > 1). A preview of a newer render (or another
// size) starts that render's generation in `image` too, with no samples: the frame shows the
// preview at once, and the render's own tiles then replace it. Returns true when either changed.
bool apply_preview_updates(PreviewImage& preview, DisplayImage& image,
                           const std::vector<TileUpdate>& updates);

TileTotals sum_tile_totals(const DisplayImage& image);

// Puts the 8-bit colours and every figure in percent (bound, noise, missed light) at another
// exposure, as a render at that exposure reports them, bit for bit: a method whose radiance does
// not depend on the exposure goes on rendering when it changes (app::restart_needed), and the
// hover, the statistics and the snapshots then read the image at the exposure shown. Returns
// true when anything changed.
bool expose_display_image(DisplayImage& image, float exposure_scale);

// Pixel error of the image against the reference (docs/design.md: |dR|+|dG|+|dB| of 765, in
// percent), over the pixels both have rendered, and the signed difference (dR+dG+dB of 765,
// method - rt) the difference view shows. Each pixel compares the two means over the same
// passes: all of them where both have as many, else the first 2^L, the most both have done (a
// method changed while the reference went on starts again from one pass), both exposed at
// `exposure_scale` (2^EV of the method's render: the reference's radiance does not depend on it,
// so it is kept across an exposure change).
struct ErrorImage {
  std::vector<float> pct;  // per pixel; negative where not comparable (yet)
  std::vector<float> difference_pct;
  double average_pct = 0.0;
  double max_pct = 0.0;
  std::size_t pixels_compared = 0;
  std::size_t pixels_rendered = 0;  // of the image: all compared when equal
  int passes = 0;                   // the fewest passes a compared pixel's means are over
  std::uint64_t image_version = 0;
  std::uint64_t reference_version = 0;
};
ErrorImage compute_error_image(const DisplayImage& image, const DisplayImage& reference,
                               float exposure_scale);

// The colour of a heatmap pixel that no sample covers yet.
extern const std::uint8_t kNotRenderedRgb[3];

// The mask view's error threshold until the user picks one, % of 765.
inline constexpr double kDefaultMaskThresholdPct = 1.0;

// The per-pixel fields of the image and its comparison with rt, for the view table's readers.
ViewPixels view_pixels(const DisplayImage& image, const ErrorImage& error,
                       double mask_threshold_pct = kDefaultMaskThresholdPct);

// RGBA texels of one view, drawn by its row of the view table (app/view_table.h): sequential
// heatmaps are viridis over the shown pixels' range, min to max (returned in `range`;
// heatmap_scale.h), the diverging map spans the row's symmetric fixed range, the mask marks the
// pixels above `mask_threshold_pct` over the dimmed image. Pixels the render has not reached show
// the preview of the same generation where it has a sample, else dark grey (heatmaps) or the
// dimmed colour of the previous render (image).
// The image view maps the radiance through `display` (exposure and curve), so a change of those
// is a new composition, never a new render.
// A/B against rt: the image view's columns from `rt_from_x` on show `reference` (rt's image of
// the same view and size) instead of the method's.
struct AbSplit {
  const DisplayImage* reference = nullptr;
  int rt_from_x = 0;
};
// A locked range (the legend's lock) replaces a min..max range rule's.
void compose_view_rgba(const DisplayImage& image, const PreviewImage& preview,
                       const ErrorImage& error, ViewMode mode, std::vector<std::uint8_t>& rgba,
                       renderer::HeatmapRange& range, const renderer::Display& display = {},
                       double mask_threshold_pct = kDefaultMaskThresholdPct, const AbSplit& ab = {},
                       const std::optional<renderer::HeatmapRange>& locked_range = std::nullopt);

// 8-bit RGB of one view for a snapshot file: the render's pixels only, never the preview. A
// locked range (the legend's lock) is used as the screen uses it, for a view whose range follows
// its data, and returned in `range`: the scale `render --heatmap-range` draws with.
std::vector<std::uint8_t> view_rgb8(
    const DisplayImage& image, const ErrorImage& error, ViewMode mode,
    renderer::HeatmapRange& range, const renderer::Display& display = {},
    double mask_threshold_pct = kDefaultMaskThresholdPct,
    const std::optional<renderer::HeatmapRange>& locked_range = std::nullopt);

}  // namespace app::viewer
