// `lev_est`: LEV plus an estimate of what it culled (thesis 6.5, future work: let LEV find the
// significant lights, then estimate the contribution of the rest). The important lights get their
// shadow rays as in `lev`; the rest, which `lev` drops, is cut into clusters and each cluster is
// estimated by a representative light carrying the cluster's intensity (Lightcuts, Walter et al.
// 2005). Deterministic: the clusters and representatives depend on the point only. At tolerance
// 0 nothing is culled and it selects exactly what `rt` selects, in the same order.
#pragma once

#include <memory>
#include <vector>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// One thread's clusters, reused from point to point.
struct LevEstScratch final : MethodScratch {
  std::vector<Light> clusters;      // representatives of what the walk culled
  std::vector<Light> bound_lights;  // the culled radiance bound's walk's, dropped
};

class LevEstSelector final : public LightSelector {
 public:
  // Fits the hierarchy's extent volumes for `tolerance` (the hierarchy itself is not changed).
  // tolerance in the scene's units; display_scale (2^EV) turns it into displayed units for the
  // share of the seen irradiance the rest is estimated above, which the displayed tolerance sets.
  LevEstSelector(const LightHierarchy& hierarchy, float tolerance, float display_scale = 1.0f);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
  std::unique_ptr<MethodScratch> make_scratch() const override {
    return std::make_unique<LevEstScratch>();
  }

 private:
  const LightHierarchy& hierarchy_;
  const ExtentVolumes volumes_;
  const float tolerance_;
  const ClusterCut cut_;
};

}  // namespace lev
