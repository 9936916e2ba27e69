// `lev_mc`: LEV with an unbiased remainder. The walk's important lights get their shadow rays
// exactly as in `lev`; what the walk culled (subtrees whose extent volume missed the point, lights
// below the tolerance) is not dropped but sampled: k lights drawn from it by the importance
// descent (light_sampling.h), one shadow ray each, weighed by 1/probability. Every light that
// can light the point is either tested or has a non-zero probability, so the expected value of
// a pass is the `rt` image (Stochastic Light Culling, Tokuyoshi and Harada 2016, reaches the same
// end by randomising the extent). At tolerance 0 nothing that can light the point is culled and
// the image equals `rt` bit for bit.
#pragma once

#include "lev/light_hierarchy.h"
#include "lev/sampling_selector.h"

namespace lev {

class LevMcSelector final : public SamplingSelector {
 public:
  // lights_per_point: k, the lights drawn from the culled rest at each shading point (>= 1).
  LevMcSelector(const LightHierarchy& hierarchy, float tolerance, int lights_per_point);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;

 private:
  const ExtentVolumes volumes_;
  const float tolerance_;
};

}  // namespace lev
