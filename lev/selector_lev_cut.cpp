#include "lev/selector_lev_cut.h"

#include <cassert>

namespace lev {

LevCutSelector::LevCutSelector(const LightHierarchy& hierarchy, float relative_error,
                               float display_scale)
    : hierarchy_(hierarchy),
      relative_error_(relative_error),
      tolerance_(relative_error * kDropToleranceOfRelativeError / display_scale),
      volumes_(fit_extent_volumes(hierarchy, tolerance_)),
      cut_nodes_(make_cut_node_table(hierarchy)) {}

glm::vec3 LevCutSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                          SelectionCounters& counters,
                                          glm::vec3* culled_irradiance_bound) const {
  scratch.lights.clear();
  WalkCounters walk_counters;
  CulledRadianceBound culled_radiance;
  if (scratch.culled_radiance && culled_irradiance_bound) {
    culled_radiance.surface = point.surface_response();
    scratch.walk.radiance = &culled_radiance;
  }
  find_light_cut(hierarchy_, volumes_, cut_nodes_, tolerance_, relative_error_, point, scratch.walk,
                 scratch.lights, walk_counters, culled_irradiance_bound);
  scratch.walk.radiance = nullptr;
  if (culled_radiance.bounded) *scratch.culled_radiance = culled_radiance;
  counters.nodes_visited += walk_counters.nodes_visited;
  counters.lights_evaluated += walk_counters.lights_evaluated;
  // The lights and the clusters' representatives alike: one shadow ray each.
  const std::size_t shaded_from = scratch.inspect ? scratch.inspect->shaded.size() : 0;
  // A centred cluster's ray goes to one of its lights (CutCluster); the rest to the light itself.
  const std::vector<CutCluster>& centred = scratch.walk.centred_clusters;
  std::size_t next_centred = 0;
  Light target;
  const auto shadow_target = [&](std::size_t i, const Light&) -> const Light* {
    while (next_centred < centred.size() && centred[next_centred].index < i) ++next_centred;
    if (next_centred == centred.size() || centred[next_centred].index != i) return nullptr;
    target = cluster_shadow_target(hierarchy_, cut_nodes_, centred[next_centred]);
    return &target;
  };
  // The walk computed each one's unshadowed radiance for its total when it cut (the same floats).
  const std::vector<glm::vec3>& estimates = scratch.walk.cut_estimates;
  assert(estimates.empty() || estimates.size() == scratch.lights.size());
  const glm::vec3* unshadowed =
      estimates.size() == scratch.lights.size() ? estimates.data() : nullptr;
  const glm::vec3 radiance = sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, point, counters, scratch.cancel, nullptr,
      scratch.inspect, shadow_target, unshadowed);
  if (scratch.inspect) scratch.inspect->attach_walk_clusters(shaded_from);
  return radiance;
}

std::size_t LevCutSelector::bookkeeping_bytes() const {
  return cut_nodes_.draw_weights.size() * sizeof(double) + cut_nodes_.centred.size() +
         (cut_nodes_.drawn_lights.size() + cut_nodes_.first_lights.size() +
          cut_nodes_.light_counts.size()) *
             sizeof(std::uint32_t);
}

}  // namespace lev
