#include "lev/selector_light_tree.h"

namespace lev {

glm::vec3 LightTreeSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                             SelectionCounters& counters,
                                             glm::vec3* culled_irradiance_bound) const {
  SamplingScratch& sampling = begin_point(scratch, culled_irradiance_bound);
  sampling.parts.clear();
  sampling.parts.subtrees.push_back(whole_hierarchy(hierarchy_, point.position()));
  // Nothing is tested exactly: every light is left to the draws, as the root's.
  if (scratch.inspect) scratch.inspect->culled_subtrees.push_back(sampling.parts.subtrees.back());
  return sampled_radiance(hierarchy_, lights_per_point_, point, scratch.random, sampling, counters,
                          nullptr, scratch.inspect);
}

}  // namespace lev
