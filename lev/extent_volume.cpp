#include "lev/extent_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lev {

float extent_radius(float light_strength, float tolerance) {
  if (!(light_strength > 0.0f)) return 0.0f;
  if (tolerance <= 0.0f) return std::numeric_limits<float>::infinity();
  const double r = std::sqrt(static_cast<double>(light_strength) / static_cast<double>(tolerance));
  return r >= static_cast<double>(std::numeric_limits<float>::max())
             ? std::numeric_limits<float>::infinity()
             : static_cast<float>(r);
}

double spot_extent_reach(double theta, double delta, double dropoff, double cos_slack) {
  constexpr double kHalfPi = M_PI / 2.0;
  // Without a dropoff the volume is the cone cut by the sphere (thesis fig. 3.1): the cone's
  // direction closest to e is e itself when the cone contains it, else the rim, delta from the
  // axis towards e; a cone pointing away from e leaves only the apex.
  if (!(dropoff > 0.0)) return std::max(0.0, std::cos(std::max(0.0, theta - delta)));
  // With Warn's dropoff (eq. 5) a direction at gamma from the axis reaches out to
  // r c^(P/2), c = cos(gamma) + cos_slack, and its projection on e is largest on the side of the
  // cone facing e: g(gamma) = c^(P/2) cos(theta - gamma). The spot is dark where c <= 0, and g is
  // positive only where theta - gamma is within 90 degrees, so gamma lies in [lo, hi].
  const double q = 0.5 * dropoff;
  const double lo = std::max(0.0, theta - kHalfPi);
  const double hi = std::min(delta, std::acos(std::clamp(-cos_slack, -1.0, 1.0)));
  if (lo > hi) return 0.0;
  // On [lo, hi] both factors are log-concave, so g has a single maximum where the derivative of
  // its log, tan(theta - gamma) - q sin(gamma) / c, changes sign; `slope` has that sign without
  // the poles (it is the derivative times c cos(theta - gamma) > 0). Refitting computes this six
  // times per spotlight and tolerance, so the search runs on t = tan(gamma / 2), which gives
  // cos(gamma) and sin(gamma) by arithmetic alone (and grows with gamma, keeping the bracket).
  const double cos_theta = std::cos(theta), sin_theta = std::sin(theta);
  struct Angle {
    double cos, sin;
  };
  const auto angle = [](double t) {
    return Angle{(1.0 - t * t) / (1.0 + t * t), 2.0 * t / (1.0 + t * t)};
  };
  const auto g = [&](Angle u) {
    const double along = cos_theta * u.cos + sin_theta * u.sin;  // cos(theta - gamma)
    return std::max(0.0, std::pow(std::max(0.0, u.cos + cos_slack), q) * along);
  };
  const auto slope = [&](Angle u) {
    return (sin_theta * u.cos - cos_theta * u.sin) * (u.cos + cos_slack) -
           q * u.sin * (cos_theta * u.cos + sin_theta * u.sin);
  };
  double a = std::tan(0.5 * lo), b = std::tan(0.5 * hi);
  if (slope(angle(a)) <= 0.0) {
    b = a;
  } else if (slope(angle(b)) >= 0.0) {
    a = b;
  } else {
    // slope > 0 at a, < 0 at b; 1e-10 in t is at most 2e-10 in gamma.
    while (b - a > 1e-10) {
      const double m = 0.5 * (a + b);
      if (m <= a || m >= b) break;
      (slope(angle(m)) > 0.0 ? a : b) = m;
    }
  }
  // The maximum lies in [a, b], where g changes by at most |g'| (b - a) <= (q + 1) (b - a) per
  // radian of gamma; that and a few ulps of rounding are added.
  const double width = 2.0 * (b - a);
  return std::max(g(angle(a)), g(angle(b))) * (1.0 + 1e-12) + (q + 1.0) * width;
}

Bounds light_extent_bounds(const Light& light, float tolerance) {
  const float r = extent_radius(strength(light), tolerance);
  if (r == 0.0f) return Bounds{};
  const bool ranged = std::isfinite(light.range);
  if (std::isinf(r) && !ranged) return infinite_bounds();
  const glm::vec3 p = light.position;
  // The radius in double, and never below the float one, so that a point at the float radius
  // (p + r computed in float) is inside too. A range caps it, at every tolerance including 0:
  // irradiance_falloff is zero where the float d^2 exceeds range^2, and that d^2 is within a few
  // ulps of the exact one (kRangeSlack covers them).
  constexpr double kRangeSlack = 1e-6;
  const double unranged = std::isinf(r) ? std::numeric_limits<double>::infinity()
                                        : std::max(std::sqrt(static_cast<double>(strength(light)) /
                                                             static_cast<double>(tolerance)),
                                                   static_cast<double>(r));
  const double radius =
      ranged ? std::min(unranged, static_cast<double>(light.range) * (1.0 + kRangeSlack))
             : unranged;
  Bounds b;
  if (light.kind == LightKind::point) {
    for (int i = 0; i < 3; ++i) {
      b.hi[i] = round_outwards(static_cast<double>(p[i]) + radius, +1);
      b.lo[i] = round_outwards(static_cast<double>(p[i]) - radius, -1);
    }
    return b;
  }
  // Along axis e_i the volume reaches r * spot_extent_reach(angle(a, e_i)) and along -e_i
  // r * spot_extent_reach(angle(a, -e_i)) = r * spot_extent_reach(pi - angle(a, e_i)). The
  // volume is the one is_important sees in float arithmetic: cos(gamma) there can come out above
  // the exact value by a few float ulps (kCosSlack covers them, widening the cone a little and
  // raising the dropoff term), and 1/d^2, pow and the comparison with the tolerance round by a few
  // more (kRelativeSlack on the reach).
  constexpr double kCosSlack = 1e-6;
  constexpr double kRelativeSlack = 1e-6;
  const double delta = std::acos(
      std::clamp<double>(static_cast<double>(light.cos_cone_half_angle) - kCosSlack, -1.0, 1.0));
  // Where the range cuts the sphere, Warn's dropoff shape scaled to the range would be too
  // small (its edge lies beyond the range); the cone cut by the range's sphere holds it.
  const bool range_cuts = radius < unranged;
  const double dropoff = range_cuts ? 0.0 : light.dropoff;
  const double reach_radius = radius * (1.0 + kRelativeSlack);
  for (int i = 0; i < 3; ++i) {
    const double theta = std::acos(std::clamp<double>(light.direction[i], -1.0, 1.0));
    const double reach_pos = spot_extent_reach(theta, delta, dropoff, kCosSlack);
    const double reach_neg = spot_extent_reach(M_PI - theta, delta, dropoff, kCosSlack);
    b.hi[i] = round_outwards(static_cast<double>(p[i]) + reach_radius * reach_pos, +1);
    b.lo[i] = round_outwards(static_cast<double>(p[i]) - reach_radius * reach_neg, -1);
  }
  return b;
}

}  // namespace lev
