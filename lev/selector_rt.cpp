#include "lev/selector_rt.h"

#include "lev/important_lights.h"

namespace lev {

RtSelector::RtSelector(const LightHierarchy& hierarchy)
    : world_lights_(flatten_lights(hierarchy)) {}

glm::vec3 RtSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                      SelectionCounters& counters,
                                      glm::vec3* culled_irradiance_bound) const {
  const glm::vec3 x = point.position();
  if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(0.0f);  // every light is tested
  return sum_visible_lights(
      world_lights_, [&](const Light& l) { return is_important(l, x, 0.0f); }, point, counters,
      scratch.cancel, nullptr, scratch.inspect);
}

}  // namespace lev
