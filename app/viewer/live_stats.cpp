#include "app/viewer/live_stats.h"

namespace app::viewer {

LiveStats collect_live_stats(const DisplayImage& image, const WorkerStatus& status,
                             const ErrorImage& error, std::chrono::steady_clock::time_point now) {
  LiveStats s;
  const bool current = image.generation == status.generation && status.generation != 0;
  if (current) {
    const TileTotals t = sum_tile_totals(image);
    s.samples = t.samples;
    s.shading_points = t.shading_points;
    s.shadow_rays = t.shadow_rays;
    s.lights_tested_max = t.lights_tested_max;
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
  }
  if (error.pixels_compared > 0) {
    s.error_avg_pct = error.average_pct;
    s.error_max_pct = error.max_pct;
    s.error_pixels = error.pixels_compared;
  }
  return s;
}

nlohmann::ordered_json live_stats_json(const LiveStats& s, const WorkerStatus& status,
                                       const Settings& settings, const renderer::Camera& camera) {
  nlohmann::ordered_json j;
  j["scene"] = status.scene;
  j["level"] = status.level;
  j["lights"] = status.light_count;
  j["method"] = status.method;
  j["tolerance"] = status.tolerance;
  j["width"] = status.width;
  j["height"] = status.height;
  j["spp"] = status.passes_done;
  j["threads"] = settings.threads;
  j["depth"] = settings.depth;
  j["subsample"] = settings.subsample;
  j["light_scale"] = settings.light_scale;
  j["camera"] = settings.camera;
  j["time_build_s"] = status.build_seconds;
  j["time_refit_s"] = status.refit_seconds;
  j["time_render_s"] = s.render_seconds;
  j["time_pass_s"] = s.pass_seconds;
  j["mrays_per_s"] = s.mrays_per_second;
  j["shading_points"] = s.shading_points;
  j["shadow_rays"] = s.shadow_rays;
  j["lights_tested_avg"] = s.lights_tested_avg;
  j["lights_tested_max"] = s.lights_tested_max;
  j["nodes_visited_avg"] = s.nodes_visited_avg;
  j["hierarchy_bytes"] = status.hierarchy_bytes;
  j["method_bytes"] = status.method_bytes;
  if (s.error_avg_pct) {
    j["pixel_error_avg_pct"] = *s.error_avg_pct;
    j["pixel_error_max_pct"] = *s.error_max_pct;
    j["pixel_error_pixels"] = s.error_pixels;
    j["pixel_error_scope"] = "pass 0 against the rt reference, pixels both have rendered";
  }
  const auto vec = [](const glm::vec3& v) {
    return nlohmann::ordered_json::array({v.x, v.y, v.z});
  };
  j["camera"] = {{"position", vec(camera.position)},
                 {"target", vec(camera.target)},
                 {"up", vec(camera.up)},
                 {"vertical_fov_deg", camera.vertical_fov_deg}};
  return j;
}

}  // namespace app::viewer
