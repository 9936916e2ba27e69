#include "lev/selector_lev.h"

#include "lev/important_lights.h"
#include "lev/missed_light.h"

namespace lev {

glm::vec3 LevSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                       SelectionCounters& counters,
                                       glm::vec3* culled_irradiance_bound) const {
  scratch.lights.clear();
  WalkCounters walk_counters;
  CulledRadianceBound culled_radiance;
  if (scratch.culled_radiance && culled_irradiance_bound) {
    culled_radiance.surface = point.surface_response();
    scratch.walk.radiance = &culled_radiance;
  }
  walk_(hierarchy_, volumes_, tolerance_, point.position(), scratch.walk, scratch.lights,
        walk_counters, culled_irradiance_bound);
  scratch.walk.radiance = nullptr;
  if (culled_radiance.bounded) *scratch.culled_radiance = culled_radiance;
  counters.nodes_visited += walk_counters.nodes_visited;
  const glm::vec3 radiance = sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, point, counters, scratch.cancel, nullptr,
      scratch.inspect);
  if (scratch.missed) {
    // lev's culled lights, less those a variant (lev_bounded) tested all the same.
    estimate_missed_light(hierarchy_, volumes_, tolerance_, point, scratch,
                          visible_radiance_below_tolerance(scratch.lights, tolerance_, point));
  }
  return radiance;
}

}  // namespace lev
