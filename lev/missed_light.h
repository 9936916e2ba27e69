// The missed-light estimate (docs/design.md "Relative error and the displayed image"): what a
// method that culls left out at a shading point, with shadows, estimated by the remainder sampler
// lev_mc already has (light_sampling.h). The lights the plain LEV walk culls at the tolerance are
// drawn K times by importance, each draw gets its shadow ray and is weighed by 1/probability, so
// the mean is an unbiased estimate of their visible radiance; a method that added something in
// their stead (lev_est's clusters) or tested some of them (lev_bounded) subtracts that, which it
// knows exactly. Where walls hide every culled light the draws find them occluded and the
// estimate reads 0, unlike the certified bound, which assumes no shadows.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/light_sampling.h"
#include "lev/light_selector.h"

namespace lev {

// The buffers of the estimate on one thread (SelectorScratch::missed_scratch).
struct MissedScratch final : MethodScratch {
  SamplingScratch sampling;
  std::vector<Light> found;  // the walk's important lights, not needed here
};

// When scratch.missed is set: fills it with the estimate of the visible radiance of the lights
// the LEV walk culls at the point for `tolerance` (volumes fitted for it or less), minus
// stand_in, the radiance the method added for part of them. The draws use missed->random; their
// work is not counted in the method's counters. Does nothing when scratch.missed is null.
void estimate_missed_light(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                           float tolerance, ShadingPoint& point, SelectorScratch& scratch,
                           const glm::vec3& stand_in);

// The visible radiance of the lights in `lights` that the LEV walk at `tolerance` would have
// culled (they fail is_important at the point): what lev_bounded tested beyond lev, one shadow
// ray each. Only asked for with the missed estimate.
glm::vec3 visible_radiance_below_tolerance(const std::vector<Light>& lights, float tolerance,
                                           ShadingPoint& point);

}  // namespace lev
