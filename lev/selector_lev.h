// `lev`: the Light Extent Volume method (thesis ch. 3): walk the hierarchy, shadow-test only the
// lights whose extent volume contains the point. At tolerance 0 it selects exactly what `rt`
// selects, in the same order, so the images are identical bit for bit.
#pragma once

#include <vector>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// The walk that picks the lights to shadow-test (important_lights.h): for `lev`
// find_important_lights_tight_bound (find_important_lights' lights, with its culled bound
// tightened where the point lies near culled lights); variants of LEV (lev_bounded) derive from
// LevSelector with their own.
using LightWalk = void (*)(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                           float tolerance, const glm::vec3& point, WalkScratch& scratch,
                           std::vector<Light>& lights, WalkCounters& counters,
                           glm::vec3* culled_irradiance_bound);

class LevSelector : public LightSelector {
 public:
  // Fits the hierarchy's extent volumes for `tolerance` (the hierarchy itself is not changed).
  LevSelector(const LightHierarchy& hierarchy, float tolerance,
              LightWalk walk = find_important_lights_tight_bound)
      : hierarchy_(hierarchy),
        volumes_(fit_extent_volumes(hierarchy, tolerance)),
        tolerance_(tolerance),
        walk_(walk) {}
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const final;

 private:
  const LightHierarchy& hierarchy_;
  const ExtentVolumes volumes_;
  const float tolerance_;
  const LightWalk walk_;
};

}  // namespace lev
