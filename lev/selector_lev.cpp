#include "lev/selector_lev.h"

#include "lev/important_lights.h"

namespace lev {

glm::vec3 LevSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                       SelectionCounters& counters) const {
  scratch.lights.clear();
  WalkCounters walk_counters;
  find_important_lights(hierarchy_, volumes_, tolerance_, point.position(), scratch.walk, scratch.lights, walk_counters);
  counters.nodes_visited += walk_counters.nodes_visited;
  return sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, point, counters, scratch.cancel);
}

}  // namespace lev
