// `lev_bounded`: LEV with a guarantee. The walk culls a subtree (or a light below the tolerance)
// only while the sum of the irradiance bounds of everything culled at this point stays within
// the tolerance, compared on the per-light test's scale (the brightest channel, lev/light.h); what
// does not fit is walked, and its lights shadow-tested, as if their volumes held the point
// (find_lights_within_budget). So the culled irradiance at every point is at most the tolerance,
// where `lev` bounds only each culled light; the price is the shadow rays the guarantee needs.
// At tolerance 0 it selects what `rt` selects, in the same order.
#pragma once

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/selector_lev.h"

namespace lev {

class LevBoundedSelector final : public LevSelector {
 public:
  LevBoundedSelector(const LightHierarchy& hierarchy, float tolerance)
      : LevSelector(hierarchy, tolerance, find_lights_within_budget) {}
};

}  // namespace lev
