// `lev`: the Light Extent Volume method (thesis ch. 3): walk the hierarchy, shadow-test only the
// lights whose extent volume contains the point. At tolerance 0 it selects exactly what `rt`
// selects, in the same order, so the images are identical bit for bit.
#pragma once

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

class LevSelector final : public LightSelector {
 public:
  // Fits the hierarchy's extent volumes for `tolerance` (the hierarchy itself is not changed).
  LevSelector(const LightHierarchy& hierarchy, float tolerance)
      : hierarchy_(hierarchy), volumes_(fit_extent_volumes(hierarchy, tolerance)), tolerance_(tolerance) {}
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters) const override;

 private:
  const LightHierarchy& hierarchy_;
  const ExtentVolumes volumes_;
  const float tolerance_;
};

}  // namespace lev
