// `lev_cut`: LEV with a relative criterion. LEV's extent volumes drop the lights that
// cannot reach the display (below the tolerance), and what they keep is cut relative to the
// shading point, as Lightcuts cuts (Walter et al. 2005): a subtree whose cluster bound
// (light_bounds.h's radiance_bound) is within the relative error of the point's running total
// costs one shadow ray (to its representative, or, for a centred one, to one of its lights:
// important_lights.h's CutCluster; a small cluster of spots aimed apart is shaded from its own
// lights' summed radiance, its ray to one of them: WalkScratch::exact_clusters); a larger one is
// walked, largest first (find_light_cut). One setting, the relative error: the tolerance the
// volumes drop at is tied to it (kDropToleranceOfRelativeError), so a tighter setting both drops
// less and cuts finer, and at 0 it drops nothing and cuts nothing: the image is `rt`'s bit for bit.
// Deterministic: the cut depends on the point only.
#pragma once

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// The tolerance lev_cut's volumes drop at, per unit of relative error: a light is dropped where
// its displayed irradiance (times the exposure, 2^EV) is below the relative error times one
// 8-bit display step (1/255), so no single dropped light moves a pixel by more than that share
// of a step at any exposure.
inline constexpr float kDropToleranceOfRelativeError = 1.0f / 255.0f;

class LevCutSelector final : public LightSelector {
 public:
  // relative_error in [0, 1]; fits the extent volumes for the tolerance it implies at the
  // exposure display_scale (2^EV, > 0).
  LevCutSelector(const LightHierarchy& hierarchy, float relative_error, float display_scale = 1.0f);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
  // The cut's table of the nodes (CutNodeTable).
  std::size_t bookkeeping_bytes() const override;

 private:
  const LightHierarchy& hierarchy_;
  const float relative_error_;
  const float tolerance_;
  const ExtentVolumes volumes_;
  const CutNodeTable cut_nodes_;
};

}  // namespace lev
