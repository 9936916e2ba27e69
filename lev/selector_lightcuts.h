// `lightcuts`: Lightcuts (Walter et al. 2005) as a peer of the LEV methods. A binary light tree
// over the scene's lights (light_cut_tree.h) and, per shading point, a cut through it refined
// until every cluster's error bound is below the relative error times the point's estimated
// total (light_cut.h); each cluster of the cut costs one shadow ray to its representative. It
// ignores the tolerance: its error is relative to what the point receives. Deterministic (the
// tree and its representatives are fixed when it is built); at relative error 0 it equals `rt`.
#pragma once

#include <memory>

#include "lev/light_cut.h"
#include "lev/light_cut_tree.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

class LightcutsSelector final : public LightSelector {
 public:
  // relative_error in [0, 1].
  LightcutsSelector(const LightHierarchy& hierarchy, float relative_error);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
  std::unique_ptr<MethodScratch> make_scratch() const override {
    return std::make_unique<CutScratch>();
  }
  // The tree's nodes and the lights' world copies.
  std::size_t bookkeeping_bytes() const override;

 private:
  const LightCutTree tree_;
  const CutSettings settings_;
};

}  // namespace lev
