#include "lev/selector_light_tree.h"

#include <limits>

#include "lev/light_sampling.h"

namespace lev {

std::unique_ptr<MethodScratch> LightTreeSelector::make_scratch() const {
  return std::make_unique<SamplingScratch>();
}

glm::vec3 LightTreeSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                             SelectionCounters& counters,
                                             glm::vec3* culled_irradiance_bound) const {
  SamplingScratch& sampling = method_scratch<SamplingScratch>(scratch);
  if (culled_irradiance_bound)
    *culled_irradiance_bound = glm::vec3(std::numeric_limits<float>::infinity());
  sampling.parts.clear();
  sampling.parts.subtrees.push_back(whole_hierarchy(hierarchy_, point.position()));
  return sampled_radiance(hierarchy_, sampling.parts, samples_per_point_, point, scratch.random,
                          sampling.part_weights, sampling.weights, counters);
}

}  // namespace lev
