// The cut of Lightcuts (Walter et al. 2005, sec. 4.2) at one shading point: starting from the
// root of the light tree (light_cut_tree.h), the cluster with the largest error bound is
// replaced by its two children, until every cluster's bound is below relative_error times the
// current estimate of the point's total radiance, or the cut holds max_size clusters. A cluster
// is estimated by its representative light carrying the cluster's intensity and one shadow ray
// to it; refining a cluster keeps its representative's shadow ray for the child that shares it.
// A single light is exact; a cluster whose bound is zero (behind the surface, outside every
// cone) adds nothing and casts no ray.
//
// The bound of a cluster is light_bounds.h's radiance_bound (the aggregate's irradiance bound
// times the material's response bound over its box, visibility 1). Compared, like the tolerance
// of the other methods, on the brightest channel. At relative error 0 the cut refines every
// cluster that could add anything (no size limit then) and sums the single lights in the tree's
// light order, which is `rt`'s: the radiance equals rt's bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "lev/light_cut_tree.h"
#include "lev/light_selector.h"

namespace lev {

// The cut size Walter et al. cap the cut at (sec. 4.2: 1000 in their results).
inline constexpr std::uint32_t kDefaultMaxCutSize = 1000;

struct CutSettings {
  float relative_error = 0.02f;  // [0, 1]
  std::uint32_t max_size = kDefaultMaxCutSize;
};

// A cluster of the cut with its estimate.
struct CutEntry {
  float bound = 0.0f;  // brightest channel of the radiance bound; 0 for an exact single light
  std::uint32_t node = 0;
  glm::vec3 estimate{0.0f};          // the representative's shadowed radiance, cluster intensity
  glm::vec3 irradiance_bound{0.0f};  // the cluster's irradiance bound (0 for a single light)
  glm::vec3 radiance_bound{0.0f};    // the cluster's radiance bound (0 for a single light)
  std::int8_t visibility = -1;       // of the representative: 1 visible, 0 occluded, -1 not cast
};

// One thread's cut, reused from point to point (nothing is allocated once warm). After
// shade_light_cut, `heap` and `final` together hold the cut.
struct CutScratch final : MethodScratch {
  std::vector<CutEntry> heap;   // clusters still refinable, largest bound on top
  std::vector<CutEntry> final;  // single lights and clusters without light at the point
};

// The direct radiance at the point by a cut through `tree`. Counts the cut's size as lights
// tested and the rays cast. culled_irradiance_bound (may be null) receives the sum of the
// irradiance bounds of the clusters estimated (what is not exact). cancel (may be null) is read
// every kCancelCheckLights refinements; once raised the result is discarded by the caller.
// cluster_error_bound (may be null) receives a bound of the radiance error of the cut (RGB): per
// cluster the larger of its estimate and its radiance bound, as the shadowed radiance it stands
// for lies in [0, the bound].
glm::vec3 shade_light_cut(const LightCutTree& tree, const CutSettings& settings,
                          ShadingPoint& point, CutScratch& scratch, SelectionCounters& counters,
                          glm::vec3* culled_irradiance_bound = nullptr,
                          const std::atomic<bool>* cancel = nullptr,
                          glm::vec3* cluster_error_bound = nullptr);

// The pixel inspector's view of the cut shade_light_cut just made in `scratch`: each cluster (a
// single light as tested, a larger one as a cluster with its lights, each measured at the point
// with its own shadow ray) appended to record.shaded.
void record_light_cut(const LightCutTree& tree, const CutScratch& scratch, ShadingPoint& point,
                      InspectRecord& record);

}  // namespace lev
