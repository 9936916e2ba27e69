// The statistics of one render (docs/design.md's metric names), as `levrt render --stats` and a
// viewer snapshot both write them: each front end fills one RenderStats, and one function turns
// it into JSON, so the two files always carry the same keys.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/settings.h"
#include "app/view_table.h"
#include "renderer/camera.h"
#include "renderer/framebuffer.h"
#include "renderer/heatmap.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_error.h"
#include "renderer/rt_fallback.h"

namespace app {

struct RenderPixelError {
  double average_pct = 0.0;
  double max_pct = 0.0;
  std::uint64_t pixels = 0;  // pixels compared
  std::string scope;         // which pixels, against what
  double reference_seconds = 0.0;
};

struct RenderStats {
  std::string scene;  // as the scene calls itself
  int level = 0;
  std::uint64_t lights = 0;
  std::string method;
  // The method's settings; the JSON writes null for one the method does not read (lev/methods.h).
  double tolerance = 0.0;
  double relative_error = 0.0;
  int lights_per_point = 0;  // lights a sampling method draws per shading point and pass
  int width = 0;
  int height = 0;
  int spp = 0;      // passes done
  int threads = 0;  // resolved: never 0
  int depth = 0;
  int subsample = 1;
  double exposure_ev = 0.0;            // the EV the image was displayed with (auto's choice too)
  bool exposure_auto = false;          // chosen by --exposure auto
  std::string display = "linear";      // the display curve
  std::size_t directional_lights = 0;  // suns, shadow-tested at every point outside the hierarchy
  double build_seconds = 0.0;
  double setup_seconds = 0.0;  // the render state: selector and extent volumes
  double render_seconds = 0.0;
  double pass_seconds = 0.0;  // the last complete pass
  renderer::FramebufferTotals totals;
  std::uint64_t rendered_pixels = 0;  // pixels with a sample (the subsample's)
  std::size_t hierarchy_bytes = 0;
  std::size_t method_bytes = 0;
  // The probe that chose between the method and rt's loop (renderer/rt_fallback.h); absent when
  // none was made (rt, a sampler, --rt-fallback off).
  std::optional<renderer::RtFallbackProbe> rt_fallback;
  std::optional<RenderPixelError> error;  // against the rt reference
  // The certified bound of that error, known without the reference (renderer/error_bound.h);
  // absent when the render did not compute it.
  std::optional<renderer::PixelErrorStats> error_bound;
  renderer::Camera camera;
  int camera_index = 0;  // which of the scene file's cameras (--camera)
  // The range of every heatmap drawn (app/view_table.h), by view: heatmap_NAME_range.
  std::map<ViewMode, renderer::HeatmapRange> heatmap_ranges;
  // The estimated standard error of the mean over passes (renderer/pixel_noise.h), from two
  // passes on (null in the JSON before).
  std::optional<double> std_error_avg_pct;
  // The missed-light estimate (renderer/missed_light.h), when asked for, its draws per shading
  // point.
  std::optional<renderer::MissedLightStats> missed;
  int missed_draws = 0;
};

// The fields the settings decide alone, the same for `render` and a viewer snapshot: threads
// (resolved), depth, subsample, exposure, display and camera index.
void set_stats_from_settings(RenderStats& stats, const Settings& settings);

nlohmann::ordered_json render_stats_json(const RenderStats& stats);

}  // namespace app
