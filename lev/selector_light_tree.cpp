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
  const glm::vec3 radiance = sampled_radiance(hierarchy_, lights_per_point_, point, scratch.random,
                                              sampling, counters, nullptr, scratch.inspect);
  // No light can reach the point (every importance zero: behind the surface, dark there): the
  // radiance is rt's, 0, and certified so, not with the sampled estimate's +inf.
  if (sampling.nothing_to_draw && culled_irradiance_bound)
    *culled_irradiance_bound = glm::vec3(0.0f);
  return radiance;
}

}  // namespace lev
