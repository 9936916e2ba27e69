// Light extent volumes (thesis 3.3): the region where a light's unshadowed irradiance is at least
// the tolerance. A point light's is the sphere of radius sqrt(I / tau); a spotlight's is its cone
// cut by that sphere. Tolerance 0 makes every volume unbounded.
#pragma once

#include "lev/bounds.h"
#include "lev/light.h"

namespace lev {

// sqrt(strength / tolerance); +inf for tolerance 0 or when the ratio overflows; 0 for a dark light.
float extent_radius(float light_strength, float tolerance);

// The smallest box around the light's extent volume (sphere, or cone cut by sphere), in the
// light's own frame. Empty for a light that can never reach the tolerance.
Bounds light_extent_bounds(const Light& light, float tolerance);

}  // namespace lev
