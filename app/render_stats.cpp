#include "app/render_stats.h"

#include <optional>

#include "lev/methods.h"
#include "renderer/tile_workers.h"

namespace app {

void set_stats_from_settings(RenderStats& stats, const Settings& settings) {
  stats.threads = renderer::worker_count(settings.image.threads);
  stats.depth = settings.image.depth;
  stats.subsample = settings.image.subsample;
  stats.exposure_ev = settings.display.exposure_ev;
  stats.exposure_auto = settings.display.exposure_auto;
  stats.display = renderer::display_curve_name(settings.display.curve);
  stats.camera_index = settings.scene.camera;
  stats.relative_error = settings.method.relative_error;
  stats.lights_per_point = settings.method.lights_per_point;
}

nlohmann::ordered_json render_stats_json(const RenderStats& s) {
  const renderer::FramebufferTotals& t = s.totals;
  const double points = t.shading_points > 0 ? static_cast<double>(t.shading_points) : 1.0;
  nlohmann::ordered_json j;
  j["scene"] = s.scene;
  j["level"] = s.level;
  j["lights"] = s.lights;
  j["method"] = s.method;
  // A setting the method does not read is null: its images do not depend on it.
  const std::optional<lev::Method> method = lev::parse_method(s.method);
  const auto reads = [&](bool lev::MethodInfo::*flag) {
    return !method || lev::method_info(*method).*flag;
  };
  const auto read_or_null = [](bool read, auto value) {
    return read ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
  };
  j["tolerance"] = read_or_null(reads(&lev::MethodInfo::uses_tolerance), s.tolerance);
  j["relative_error"] =
      read_or_null(reads(&lev::MethodInfo::uses_relative_error), s.relative_error);
  j["lights_per_point"] = read_or_null(reads(&lev::MethodInfo::stochastic), s.lights_per_point);
  j["width"] = s.width;
  j["height"] = s.height;
  j["spp"] = s.spp;
  j["threads"] = s.threads;
  j["depth"] = s.depth;
  j["subsample"] = s.subsample;
  j["exposure_ev"] = s.exposure_ev;
  j["exposure_auto"] = s.exposure_auto;
  j["display"] = s.display;
  j["directional_lights"] = s.directional_lights;
  j["time_build_s"] = s.build_seconds;
  j["time_setup_s"] = s.setup_seconds;
  j["time_render_s"] = s.render_seconds;
  j["time_pass_s"] = s.pass_seconds;
  if (s.subsample > 1) {
    // The rendered pixels' time scaled to every pixel of the frame.
    const double frame_pixels = static_cast<double>(s.width) * s.height;
    j["time_render_full_frame_estimate_s"] =
        s.rendered_pixels > 0
            ? s.render_seconds * frame_pixels / static_cast<double>(s.rendered_pixels)
            : 0.0;
  }
  j["mrays_per_s"] = s.render_seconds > 0.0
                         ? static_cast<double>(t.samples + t.shadow_rays) / s.render_seconds * 1e-6
                         : 0.0;
  j["shading_points"] = t.shading_points;
  j["shadow_rays"] = t.shadow_rays;
  j["lights_tested_avg"] = static_cast<double>(t.lights_tested) / points;
  j["lights_tested_max"] = t.lights_tested_max;
  j["nodes_visited_avg"] = static_cast<double>(t.nodes_visited) / points;
  j["hierarchy_bytes"] = s.hierarchy_bytes;
  j["method_bytes"] = s.method_bytes;
  if (s.rt_fallback) {
    j["rt_fallback"] = {{"used", s.rt_fallback->use_rt},
                        {"probe_points", s.rt_fallback->points},
                        {"method_cost_rays", s.rt_fallback->method_cost_rays},
                        {"rt_cost_rays", s.rt_fallback->rt_cost_rays},
                        {"rt_cost_is_lower_bound", s.rt_fallback->rt_cost_is_lower_bound}};
  } else {
    j["rt_fallback"] = nullptr;
  }
  if (s.error_bound) {
    j["error_bound_avg_pct"] = s.error_bound->average_pct;
    j["error_bound_max_pct"] = s.error_bound->max_pct;
  }
  if (s.error) {
    j["pixel_error_avg_pct"] = s.error->average_pct;
    j["pixel_error_max_pct"] = s.error->max_pct;
    j["pixel_error_pixels"] = s.error->pixels;
    j["pixel_error_scope"] = s.error->scope;
    j["time_reference_s"] = s.error->reference_seconds;
  }
  const auto vec = [](const glm::vec3& v) {
    return nlohmann::ordered_json::array({v.x, v.y, v.z});
  };
  j["camera"] = {{"index", s.camera_index},
                 {"position", vec(s.camera.position)},
                 {"target", vec(s.camera.target)},
                 {"up", vec(s.camera.up)},
                 {"vertical_fov_deg", s.camera.vertical_fov_deg},
                 {"orthographic_half_height", s.camera.orthographic_half_height}};
  for (const ViewInfo& view : view_table()) {
    const auto range = s.heatmap_ranges.find(view.mode);
    if (range == s.heatmap_ranges.end()) continue;
    j[std::string("heatmap_") + view.name + "_range"] = {range->second.min, range->second.max};
  }
  j["heatmap_scale"] = "log(1 + value per sample), viridis";
  // null before a second pass: no spread between passes is known yet.
  if (s.std_error_avg_pct) {
    j["std_error_avg_pct"] = *s.std_error_avg_pct;
  } else {
    j["std_error_avg_pct"] = nullptr;
  }
  if (s.missed) {
    j["missed_draws"] = s.missed_draws;
    j["missed_estimate_avg_pct"] = s.missed->average_pct;
    j["missed_estimate_max_pct"] = s.missed->max_pct;
    j["missed_estimate_std_error_avg_pct"] = s.missed->std_error_avg_pct;
  }
  return j;
}

}  // namespace app
