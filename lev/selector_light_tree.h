// `light_tree`: the peer users would pick instead of LEV, pbrt-v4's BVHLightSampler and Cycles'
// light tree: no deterministic part, k lights drawn from the whole hierarchy at each shading
// point by the importance descent (light_sampling.h, the same importance pbrt-v4 uses: the
// aggregate's intensity over the clamped distance, its spot cones and the cosine at the surface
// normal), one shadow ray each, weighed by 1/probability. Unbiased: passes converge to `rt`.
// Like lev_mc's culled parts, the hierarchy is first opened where its spots aim apart
// (open_wide_parts), so that both methods draw through the same importance.
#pragma once

#include "lev/light_hierarchy.h"
#include "lev/sampling_selector.h"

namespace lev {

class LightTreeSelector final : public SamplingSelector {
 public:
  LightTreeSelector(const LightHierarchy& hierarchy, int lights_per_point)
      : SamplingSelector(hierarchy, lights_per_point) {}
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
};

}  // namespace lev
