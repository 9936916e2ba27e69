// `levrt render`: render a scene headless with one method and write the image, the heatmaps and
// the statistics (app/render_stats.h), optionally against an `rt` reference.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/accuracy_gate.h"
#include "app/exr_encoding.h"
#include "app/output_files.h"
#include "app/scene_loading.h"
#include "app/settings.h"
#include "app/view_table.h"
#include "renderer/heatmap.h"
#include "renderer/render_service.h"

namespace app {

struct RenderOutputs {
  std::string image;  // PNG (the displayed image) or EXR (radiance and channels)
  std::string stats;  // JSON
  // The heatmap PNGs asked for, by view (app/view_table.h: the rows with an output flag). The
  // missed-light heatmap turns the estimate on (kDefaultMissedDraws draws unless
  // --missed-draws says); the error heatmap, the reference's own image PNG and the accuracy
  // gate (exit 3 above it) need reference_rt.
  std::map<ViewMode, std::string> heatmaps;
  // --heatmap-range: every heatmap drawn over this range (renderer::heatmap_position's scale)
  // instead of its own 0..max, so renders are compared on one scale.
  std::optional<renderer::HeatmapRange> heatmap_range;
  std::string reference_image;
  std::optional<AccuracyGate> fail_above;
  bool reference_rt = false;
  bool quiet = false;  // no progress, no summary, no "wrote" line
};

// --heatmap-range LO,HI: two finite numbers, 0 <= LO < HI; throws UsageError (naming the flag
// and the text) otherwise.
renderer::HeatmapRange parse_heatmap_range(const std::string& text);

// The outputs render writes, in the order of the "wrote" line.
std::vector<OutputPath> render_output_paths(const RenderOutputs& outputs);

// Peak memory of `levrt render` per image pixel (framebuffer, counters, heatmaps; the reference
// adds a second framebuffer), measured as the slope of peak RSS (/usr/bin/time -v) between
// 2048x2048 and 4096x4096 renders with --subsample 64 and every output: subsampling does not
// reduce it, the framebuffer is full size. (Measured: 123 and 183 bytes with the error bound's
// per-pixel sum and heatmap; then 24 and 48 bytes counted, not measured, for the variance sums
// and the noise heatmap, and 12 and 24 for the square sums held in double.)
inline constexpr std::uint64_t kRenderBytesPerPixel = 160;
inline constexpr std::uint64_t kReferenceRenderBytesPerPixel = 256;
// The memory a render may plan for; larger images are refused before any work.
inline constexpr std::uint64_t kRenderMemoryBudgetBytes = std::uint64_t{8} << 30;

// Why width x height (with or without the rt reference) would need more than budget_bytes, in one
// line naming the size; empty when it fits.
std::string memory_budget_refusal(const Settings& settings, bool reference,
                                  std::uint64_t budget_bytes = kRenderMemoryBudgetBytes);
// Throws UsageError with memory_budget_refusal's line when it is not empty.
void check_memory_budget(const Settings& settings, bool reference);

// Renders settings.spp passes of `method` over the loaded scene through the render service.
// Throws Interrupted when *cancel is raised (Ctrl-C) before the last pass completes.
// show_progress: after each pass, once the render has run a second, a line on stderr with the
// passes done and an estimate of the time left (rewritten in place; for a terminal).
renderer::RenderResult render_image(const LoadedScene& loaded, const Settings& settings,
                                    lev::Method method, const std::atomic<bool>* cancel = nullptr,
                                    bool show_progress = false);

int run_render(const Settings& settings, const RenderOutputs& outputs);

// The channels `--out FILE.exr` writes (app/exr_encoding.h): R, G, B the mean scene-linear
// radiance (before the exposure), `samples`, `lights_tested` and `nodes_visited` (per sample),
// `error_bound_pct` and `noise_pct` (renderer/error_bound.h, pixel_noise.h, on the displayed
// scale), `missed_pct` when the missed light was estimated, and `error_pct` (the error against
// the rt reference, pixel order) when error_pct is not empty.
std::vector<ExrChannel> framebuffer_exr_channels(const renderer::Framebuffer& framebuffer,
                                                 const std::vector<double>& error_pct);

}  // namespace app
