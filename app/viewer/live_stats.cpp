#include "app/viewer/live_stats.h"

#include <algorithm>
#include <cstdio>

#include "renderer/error_bound.h"

namespace app::viewer {
namespace {

std::optional<double> noise_average_pct(const DisplayImage& image) {
  double sum = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < image.noise_pct.size(); ++i) {
    if (image.samples[i] < 2) continue;
    sum += image.noise_pct[i];
    ++pixels;
  }
  if (pixels == 0) return std::nullopt;
  return sum / static_cast<double>(pixels);
}

// Over the rendered pixels, as renderer::error_bound_stats does over a framebuffer's totals, but
// from the pixels at the exposure shown (the tiles' totals are at the render's).
std::optional<renderer::PixelErrorStats> error_bound_stats(const DisplayImage& image) {
  renderer::PixelErrorStats s;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < image.error_bound_pct.size(); ++i) {
    if (image.samples[i] == 0) continue;
    s.average_pct += image.error_bound_pct[i];
    s.max_pct = std::max(s.max_pct, static_cast<double>(image.error_bound_pct[i]));
    ++pixels;
  }
  if (pixels == 0) return std::nullopt;
  s.average_pct /= static_cast<double>(pixels);
  return s;
}

// Over the rendered pixels, as renderer::missed_light_stats does over a framebuffer.
std::optional<renderer::MissedLightStats> missed_light_stats(const DisplayImage& image) {
  if (!image.has_missed) return std::nullopt;
  renderer::MissedLightStats s;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < image.missed_pct.size(); ++i) {
    if (image.samples[i] == 0) continue;
    s.average_pct += image.missed_pct[i];
    s.max_pct = std::max(s.max_pct, static_cast<double>(image.missed_pct[i]));
    s.std_error_avg_pct += image.missed_std_error_pct[i];
    ++pixels;
  }
  if (pixels == 0) return std::nullopt;
  s.average_pct /= static_cast<double>(pixels);
  s.std_error_avg_pct /= static_cast<double>(pixels);
  return s;
}

}  // namespace

std::string method_text(const lev::MethodChoice& choice) {
  const lev::MethodInfo& method = lev::method_info(choice.method);
  char text[96];
  if (method.uses_tolerance) {
    std::snprintf(text, sizeof text, "%s, tolerance %g", method.name, choice.tolerance);
  } else if (method.uses_relative_error) {
    std::snprintf(text, sizeof text, "%s, relative error %g", method.name, choice.relative_error);
  } else {
    std::snprintf(text, sizeof text, "%s", method.name);
  }
  std::string out = text;
  if (method.stochastic) {
    std::snprintf(text, sizeof text, ", %d light%s per point", choice.lights_per_point,
                  choice.lights_per_point == 1 ? "" : "s");
    out += text;
  }
  return out;
}

std::string nodes_visited_text(double nodes_visited_avg, std::uint64_t shading_points,
                               const char* method_name, bool rt_loop) {
  char text[96];
  if (shading_points == 0 || nodes_visited_avg != 0.0) {
    std::snprintf(text, sizeof text, "%.2f avg", nodes_visited_avg);
  } else if (rt_loop) {
    std::snprintf(text, sizeof text, "none (shaded with rt's loop)");
  } else {
    std::snprintf(text, sizeof text, "none (%s walks no light hierarchy)", method_name);
  }
  return text;
}

LiveStats collect_live_stats(const DisplayImage& image, const WorkerStatus& status,
                             const ErrorImage& error, std::chrono::steady_clock::time_point now) {
  LiveStats s;
  const bool current = image.generation == status.generation && status.generation != 0;
  if (current) {
    const TileTotals t = sum_tile_totals(image);
    s.totals = t;
    s.samples = t.samples;
    s.shading_points = t.shading_points;
    s.shadow_rays = t.shadow_rays;
    s.lights_tested_max = t.lights_tested_max;
    s.error_bound = error_bound_stats(image);
    if (t.shading_points > 0) {
      s.lights_tested_avg =
          static_cast<double>(t.lights_tested) / static_cast<double>(t.shading_points);
      s.nodes_visited_avg =
          static_cast<double>(t.nodes_visited) / static_cast<double>(t.shading_points);
    }
    s.render_seconds = elapsed_render_seconds(status, now);
    s.pass_seconds = status.passes_done > 0 ? status.last_pass_seconds : s.render_seconds;
    if (s.render_seconds > 0.0) {
      s.mrays_per_second = static_cast<double>(s.samples + s.shadow_rays) / s.render_seconds * 1e-6;
    }
    s.noise_avg_pct = noise_average_pct(image);
    s.missed = missed_light_stats(image);
  }
  if (error.pixels_compared > 0) {
    s.error_avg_pct = error.average_pct;
    s.error_max_pct = error.max_pct;
    s.error_pixels = error.pixels_compared;
    s.error_passes = error.passes;
  }
  return s;
}

RenderStats snapshot_stats(const LiveStats& s, const WorkerStatus& status, const Settings& settings,
                           const renderer::Camera& camera) {
  RenderStats r;
  r.scene = status.scene_name;
  r.level = status.scene_level;  // as render's stats: the scene's own (a file's, not the flag's)
  r.lights = status.light_count;
  r.method = lev::method_info(status.method).name;
  r.tolerance = status.tolerance;
  r.width = status.width;
  r.height = status.height;
  r.spp = status.passes_done;
  set_stats_from_settings(r, settings);
  r.directional_lights = status.directional_lights;
  r.build_seconds = status.build_seconds;
  r.setup_seconds = status.setup_seconds;
  r.render_seconds = s.render_seconds;
  r.pass_seconds = s.pass_seconds;
  r.totals = s.totals;
  // Every pass samples the same pixels once.
  r.rendered_pixels = status.passes_done > 0
                          ? s.totals.samples / static_cast<std::uint64_t>(status.passes_done)
                          : s.totals.samples;
  r.hierarchy_bytes = status.hierarchy_bytes;
  r.method_bytes = status.method_bytes;
  r.rt_fallback = status.rt_fallback;
  r.error_bound = s.error_bound;
  if (s.error_avg_pct) {
    r.error = RenderPixelError{*s.error_avg_pct, *s.error_max_pct, s.error_pixels,
                               "the mean over the same passes (" + std::to_string(s.error_passes) +
                                   ") against the rt reference's, pixels both have rendered",
                               status.reference_seconds};
  }
  r.std_error_avg_pct = s.noise_avg_pct;
  if (s.missed) {
    r.missed = s.missed;
    r.missed_draws = status.missed_draws;
  }
  r.camera = camera;
  return r;
}

}  // namespace app::viewer
