#include "lev/selector_lev_mc.h"

#include "lev/important_lights.h"
#include "lev/light_sampling.h"

namespace lev {

LevMcSelector::LevMcSelector(const LightHierarchy& hierarchy, float tolerance, int lights_per_point)
    : SamplingSelector(hierarchy, lights_per_point),
      volumes_(fit_extent_volumes(hierarchy, tolerance)),
      tolerance_(tolerance) {}

glm::vec3 LevMcSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                         SelectionCounters& counters,
                                         glm::vec3* culled_irradiance_bound) const {
  SamplingScratch& sampling = begin_point(scratch, culled_irradiance_bound);
  scratch.lights.clear();
  WalkCounters walk_counters;
  find_important_and_culled(hierarchy_, volumes_, tolerance_, point.position(), scratch.walk,
                            scratch.lights, walk_counters, sampling.parts);
  counters.nodes_visited += walk_counters.nodes_visited;
  const glm::vec3 tested = sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, point, counters, scratch.cancel, nullptr,
      scratch.inspect);
  if (tolerance_ == 0.0f || (sampling.parts.subtrees.empty() && sampling.parts.lights.empty())) {
    // Nothing culled here (a point every light reaches), or only lights dark at the point
    // (tolerance 0: is_important asks for an irradiance above 0; past their ranges the walk culls
    // lights there, and their draws found nothing): the radiance is rt's, exact, so the
    // certified bound is 0, not the sampled estimate's +inf, and no draw is made.
    if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(0.0f);
    return tested;
  }
  const glm::vec3 sampled = sampled_radiance(hierarchy_, lights_per_point_, point, scratch.random,
                                             sampling, counters, nullptr, scratch.inspect);
  // What the walk culled cannot reach the point (every importance zero): exact, as above.
  if (sampling.nothing_to_draw && culled_irradiance_bound)
    *culled_irradiance_bound = glm::vec3(0.0f);
  return tested + sampled;
}

}  // namespace lev
