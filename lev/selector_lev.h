// `lev`: the Light Extent Volume method (thesis ch. 3): walk the hierarchy, shadow-test only the
// lights whose extent volume contains the point. At tolerance 0 it selects exactly what `rt`
// selects, in the same order, so the images are identical bit for bit.
#pragma once

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

class LevSelector final : public LightSelector {
 public:
  explicit LevSelector(const LightHierarchy& hierarchy) : hierarchy_(hierarchy) {}
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters) const override;

 private:
  const LightHierarchy& hierarchy_;
};

}  // namespace lev
