#include "renderer/rt_fallback.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "lev/important_lights.h"
#include "lev/methods.h"
#include "renderer/denormal_mode.h"
#include "renderer/render.h"
#include "renderer/shading.h"

namespace renderer {

namespace {

// rt's work at a point without its shadow rays: every light it would test and every ray it would
// cast is counted (lights_tested, shadow_rays) but none is cast, and nothing is returned.
class RtWorkCounter final : public lev::LightSelector {
 public:
  explicit RtWorkCounter(std::vector<lev::Light> world_lights)
      : world_lights_(std::move(world_lights)) {}

  glm::vec3 direct_radiance(lev::ShadingPoint& point, lev::SelectorScratch&,
                            lev::SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override {
    if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(0.0f);
    const glm::vec3 x = point.position();
    for (const lev::Light& light : world_lights_) {
      if (!lev::is_important(light, x, 0.0f)) continue;  // rt's own test (selector_rt.cpp)
      ++counters.lights_tested;
      if (point.unshadowed_radiance(light) != glm::vec3(0.0f)) ++counters.shadow_rays;
    }
    return glm::vec3(0.0f);
  }

 private:
  std::vector<lev::Light> world_lights_;
};

// The counters of one selector over the probe grid's first hits (no reflection, no refraction).
PathCounters probe_counters(const Scene& scene, const RayScene& rays,
                            const RenderSettings& settings, const lev::LightSelector& selector,
                            int side) {
  lev::SelectorScratch scratch;
  TraceContext context{scene, rays, selector, scratch, 0};
  PathCounters counters;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const int x = std::min(settings.width - 1, (2 * i + 1) * settings.width / (2 * side));
      const int y = std::min(settings.height - 1, (2 * j + 1) * settings.height / (2 * side));
      const Ray ray =
          pixel_sample_ray(settings, scene.camera, x, y, 0, scratch.random, context.missed_random);
      trace_radiance(context, ray, 0, counters);
    }
  }
  return counters;
}

// The work of the probe's points, in shadow rays per point.
double cost_in_rays(const PathCounters& counters, const lev::WorkCost& cost,
                    std::size_t light_count, int points) {
  const lev::SelectionCounters& work = counters.selection;
  const double total = static_cast<double>(work.shadow_rays) +
                       cost.per_node_visited * static_cast<double>(work.nodes_visited) +
                       cost.per_light_tested * static_cast<double>(work.lights_tested) +
                       cost.per_light_evaluated * static_cast<double>(work.lights_evaluated) +
                       cost.per_scene_light * static_cast<double>(light_count) *
                           static_cast<double>(counters.shading_points);
  return total / points;
}

}  // namespace

int probe_grid_side(std::size_t light_count) {
  const double side = std::floor(std::sqrt(kProbeLightBudget / std::max<double>(1.0, light_count)));
  return static_cast<int>(std::clamp<double>(side, kMinProbeGridSide, kProbeGridSide));
}

RtFallbackProbe probe_rt_fallback(const Scene& scene, const RayScene& rays,
                                  const RenderSettings& settings,
                                  const lev::LightSelector& selector) {
  DenormalModeGuard denormals;
  const std::size_t light_count = scene.lights.light_count;
  const int side = probe_grid_side(light_count);
  RtFallbackProbe probe;
  probe.points = side * side;
  const PathCounters method = probe_counters(scene, rays, settings, selector, side);
  probe.method_cost_rays =
      cost_in_rays(method, lev::method_info(settings.method).work_cost, light_count, probe.points);
  const lev::WorkCost& rt_cost = lev::method_info(lev::reference_method()).work_cost;
  // rt's scan of every light at every hit alone, a lower bound of its work: where the method's
  // work is below it (a walk that culls well among many lights), rt's rays need no counting.
  PathCounters rt_scan;
  rt_scan.shading_points = method.shading_points;
  probe.rt_cost_rays = cost_in_rays(rt_scan, rt_cost, light_count, probe.points);
  if (probe.method_cost_rays < probe.rt_cost_rays) {
    probe.rt_cost_is_lower_bound = true;
    return probe;
  }
  const RtWorkCounter rt_counter(lev::flatten_lights(scene.lights));
  const PathCounters rt = probe_counters(scene, rays, settings, rt_counter, side);
  probe.rt_cost_rays = cost_in_rays(rt, rt_cost, light_count, probe.points);
  probe.use_rt = probe.rt_cost_rays > 0.0 && probe.method_cost_rays >= probe.rt_cost_rays;
  return probe;
}

}  // namespace renderer
