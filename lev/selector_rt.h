// `rt`: the traditional ray tracer's direct lighting, a shadow ray to every light that can light
// the point (the baseline of thesis Tables 1-2 and the reference for pixel errors).
#pragma once

#include <vector>

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

class RtSelector final : public LightSelector {
 public:
  explicit RtSelector(const LightHierarchy& hierarchy);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;

 private:
  std::vector<Light> world_lights_;
};

}  // namespace lev
