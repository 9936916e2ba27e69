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
  if (tolerance_ == 0.0f) {
    // At tolerance 0 the walk culls only lights dark at the point (is_important asks for an
    // irradiance above 0), which add nothing to rt's image either: the bound is 0. The culled
    // subtrees' aggregate bounds do not know a light's range, so past the ranges they said up to
    // 10 % of an image equal to rt's.
    if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(0.0f);
    culled_radiance.bound = glm::vec3(0.0f);
  }
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
