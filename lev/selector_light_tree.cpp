#include "lev/selector_light_tree.h"

namespace lev {

glm::vec3 LightTreeSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                             SelectionCounters& counters,
                                             glm::vec3* culled_irradiance_bound) const {
  SamplingScratch& sampling = begin_point(scratch, culled_irradiance_bound);
  sampling.parts.clear();
  sampling.parts.subtrees.push_back(whole_hierarchy(hierarchy_, point.position()));
  return sampled_radiance(hierarchy_, samples_per_point_, point, scratch.random, sampling,
                          counters);
}

}  // namespace lev
