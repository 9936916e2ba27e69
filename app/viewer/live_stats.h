// The statistics the panel shows and a snapshot writes, computed on the UI thread from the tiles
// it has received and the worker's status.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "app/render_stats.h"
#include "app/settings.h"
#include "app/viewer/display_image.h"
#include "app/viewer/render_worker.h"
#include "lev/methods.h"
#include "renderer/camera.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_error.h"

namespace app::viewer {

struct LiveStats {
  renderer::FramebufferTotals totals;  // of the tiles received
  std::uint64_t samples = 0;           // primary rays
  std::uint64_t shading_points = 0;
  std::uint64_t shadow_rays = 0;
  double lights_tested_avg = 0.0;  // per shading point
  std::uint32_t lights_tested_max = 0;
  double nodes_visited_avg = 0.0;
  double render_seconds = 0.0;    // this render so far
  double pass_seconds = 0.0;      // the last complete pass, or the running first pass so far
  double mrays_per_second = 0.0;  // primary and shadow rays
  std::optional<double> error_avg_pct;
  std::optional<double> error_max_pct;
  std::size_t error_pixels = 0;
  int error_passes = 0;  // the means compared are over this many passes (ErrorImage::passes)
  // The certified bound of that error over the pixels received, known without the reference.
  std::optional<renderer::PixelErrorStats> error_bound;
  // The estimated standard error of the mean over passes (renderer/pixel_noise.h), averaged over
  // the pixels with two samples or more; none before the second pass reaches a pixel.
  std::optional<double> noise_avg_pct;
  // The missed-light estimate over the pixels received, while the render estimates it.
  std::optional<renderer::MissedLightStats> missed;
};

// `error` is used when it has compared pixels.
LiveStats collect_live_stats(const DisplayImage& image, const WorkerStatus& status,
                             const ErrorImage& error, std::chrono::steady_clock::time_point now);

// The stats panel's method row: the method and the settings it reads (its tolerance, or its
// relative error, and the lights a sampling method draws per point), from the render's choice.
std::string method_text(const lev::MethodChoice& choice);

// The stats panel's nodes-visited row: the average, or why there is none where points were
// shaded without a walk (rt_loop: the rt fallback shaded with rt's loop; else the method walks no
// hierarchy).
std::string nodes_visited_text(double nodes_visited_avg, std::uint64_t shading_points,
                               const char* method_name, bool rt_loop);

// What a snapshot's stats JSON says (app/render_stats.h, the keys of `levrt render --stats`); the
// heatmap ranges are the caller's.
RenderStats snapshot_stats(const LiveStats& stats, const WorkerStatus& status,
                           const Settings& settings, const renderer::Camera& camera);

}  // namespace app::viewer
