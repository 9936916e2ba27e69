// `lev_cut`: LEV with a relative criterion. LEV's extent volumes drop the lights that
// cannot reach the display (below the tolerance), and what they keep is cut relative to the
// shading point, as Lightcuts cuts (Walter et al. 2005): a subtree whose cluster bound
// (light_bounds.h's radiance_bound) is within the relative error of the point's running total
// (or of kTotalFloorOfWhite of the display's white, where the total is less)
// costs one shadow ray (to its representative, or, for a centred one, to one of its lights:
// important_lights.h's CutCluster; a small cluster of spots aimed apart is shaded from its own
// lights' summed radiance, its ray to one of them: WalkScratch::exact_clusters); a larger one is
// walked, largest first (find_light_cut). One setting, the relative error: the tolerance the
// volumes drop at is tied to it (kDropToleranceOfRelativeError), so a tighter setting both drops
// less and cuts finer, and at 0 it drops nothing and cuts nothing: the image is `rt`'s bit for bit.
// Where the cut's rays find its clusters partly hidden, their 0/1 rays are noisy
// (visibility_noise.h): at such a point the cut is made finer, at half the relative error, up to
// kNoiseRefinements times, until kNoiseSigmas times that noise, on the display, is within the
// relative error; a finer cut goes on from the last one (refine_light_cut: its clusters opened
// where their bounds now exceed the criterion) rather than walking from the root again. Where the
// rays hide most of the total the cut was made relative to, it is refined relative to what they
// show (kShownErrorAllowance), on the same rounds.
// Deterministic: the cut depends on the point only.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// The tolerance lev_cut's volumes drop at, per unit of relative error: a light is dropped where
// its displayed irradiance (times the exposure, 2^EV) is below the relative error times one
// 8-bit display step (1/255), so no single dropped light moves a pixel by more than that share
// of a step at any exposure.
inline constexpr float kDropToleranceOfRelativeError = 1.0f / 255.0f;

// The noise check (LevCutSelector::direct_radiance): a point's cut is refined while this many
// standard deviations of its rays' visibility noise, times the exposure, exceed the relative
// error (a share of the display's white before the display curve: the pixel error's scale under
// the linear display; a curve steeper in the darks, sRGB's, shows dark pixels' noise larger),
// at most this many times, halving the relative error each time. Three deviations: among
// thousands of pixels a few sit that far out, and the maximum error is set by those (hall 16,384
// at 0.03: two deviations leave max 3.01 %, four spend 16 % more rays; docs/results/lev_cut.md).
// Two refinements: a third, where the noise still exceeds the setting at a quarter of it, left
// every maximum error as it was and cost 8-15 % more rays (hall 4,096 at 0.02 and 0.025, hall
// 16,384 at 0.025 and 0.03, the stage at 0.01 and 0.02; averages 0.00-0.01 points lower).
inline constexpr double kNoiseSigmas = 3.0;
inline constexpr int kNoiseRefinements = 2;

// The hidden check (LevCutSelector::direct_radiance): the cut is made relative to the total its
// lights would give unshadowed; where its rays show less of that total than 1 / this factor (a
// bright light behind a wall), each cluster's bound may exceed the relative error of what the
// pixel shows by more than this factor, and the cut is refined at the relative error that holds
// them within it, on the same rounds as the noise check. Not 1: the usual partly hidden point (a
// wall behind it, the rig's cans) is not cut again for bounds at most twice the setting.
inline constexpr float kShownErrorAllowance = 2.0f;

// A shadow ray cast at the current point: the light's position (its float bits) and whether the
// ray found it. A refined cut keeps many of the cut's clusters and lights, whose rays go to the
// same positions: they are answered from these, not cast again.
struct CastRay {
  std::uint32_t position_bits[3];
  bool visible;
};

// lev_cut's buffers for one thread: the shading loop's ray outcomes (visibility_noise) and the
// rays cast at the point so far, in the order cast and sorted for lookup.
struct LevCutScratch : MethodScratch {
  std::vector<std::uint8_t> ray_visible;
  std::vector<CastRay> rays_cast;
  std::vector<CastRay> rays_sorted;
};

class LevCutSelector final : public LightSelector {
 public:
  // relative_error in [0, 1]; fits the extent volumes for the tolerance it implies at the
  // exposure display_scale (2^EV, > 0). noise_sigmas is the noise check's (0 checks nothing: one
  // cut per point, for tests that compare).
  LevCutSelector(const LightHierarchy& hierarchy, float relative_error, float display_scale = 1.0f,
                 double noise_sigmas = kNoiseSigmas);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
  // The cut's table of the nodes (CutNodeTable).
  std::size_t bookkeeping_bytes() const override;
  std::unique_ptr<MethodScratch> make_scratch() const override {
    return std::make_unique<LevCutScratch>();
  }

 private:
  // The cut in scratch.lights shaded (its shadow rays cast through `shading`: `point` with its
  // rays remembered, RememberedRays in the .cpp), the outcomes in `ray_visible`.
  glm::vec3 shade_cut(ShadingPoint& shading, SelectorScratch& scratch, SelectionCounters& counters,
                      std::vector<std::uint8_t>& ray_visible) const;

  const LightHierarchy& hierarchy_;
  const float relative_error_;
  const float display_scale_;
  const double noise_sigmas_;
  const float tolerance_;
  const ExtentVolumes volumes_;
  const CutNodeTable cut_nodes_;
};

}  // namespace lev
