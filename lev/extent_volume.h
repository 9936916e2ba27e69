// Light extent volumes (thesis 3.3): the region where a light's unshadowed irradiance is at least
// the tolerance. A point light's is the sphere of radius sqrt(I / tau). A spotlight's lies inside
// its cone cut by that sphere, and with a dropoff it is smaller still: Warn's falloff
// I cos(gamma)^P / d^2 >= tau (thesis eq. 5) holds only out to d = sqrt(I / tau) cos(gamma)^(P/2),
// and its box is what the hierarchy stores. Tolerance 0 makes every volume unbounded, except
// that a light's range (glTF) caps the radius at every tolerance. The smooth spot profile never
// exceeds 1, so its volume is bounded by the hard cone's (spot_profile.h).
#pragma once

#include "lev/bounds.h"
#include "lev/light.h"

namespace lev {

// sqrt(strength / tolerance); +inf for tolerance 0 or when the ratio overflows; 0 for a dark light.
float extent_radius(float light_strength, float tolerance);

// How far along a unit direction e the spotlight's extent volume reaches, as a fraction of its
// extent radius: the largest (x - p).e / r over the points x of the volume, 0 when the volume lies
// wholly behind the plane through the apex. theta is the angle between the spot axis and e, delta
// the cone half-angle, dropoff Warn's P; with a dropoff, cos(gamma) + cos_slack stands for
// cos(gamma) (room for float rounding in the exact test). Never below the exact value.
double spot_extent_reach(double theta, double delta, double dropoff, double cos_slack = 0.0);

// The smallest box around the light's extent volume, in the light's own frame, as is_important
// evaluates it in float (a few ulps wider than the exact volume; every rounding moves the faces
// outwards). Empty for a light that can never reach the tolerance.
Bounds light_extent_bounds(const Light& light, float tolerance);

}  // namespace lev
