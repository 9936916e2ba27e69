// Light aggregates: what all the lights of a subtree could add together at a point, known without
// visiting them (the cluster bounds of Lightcuts, Walter et al. 2005; pbrt-v4 keeps the same idea
// in its LightBounds). An aggregate holds the summed RGB intensity of the lights, a box around
// their positions and, for spotlights, a cone of directions their axes lie in plus the widest
// cone they shine into. From it irradiance_bound gives an upper bound of the summed unshadowed
// irradiance of the lights (light.h's irradiance(), thesis eq. 1 and 5) at any point:
//
//   sum_i I_i f_i(x) / d_i^2  <=  (sum_i I_i) * max_i f_i(x) / min_i d_i^2
//
// where d_i >= the distance from x to the box, and f_i, Warn's cos(gamma)^P inside the cone and 0
// outside, is at most 1, 0 once the angle from every possible axis to x exceeds the widest cone,
// and cos(gamma) when every spot has P >= 1. An aggregate is stated in one node's frame; the
// light model is the same in every frame up to the scale, because an instance scaled by s
// multiplies intensity by s^2 and distances by s (transform.h), so the bound of a node evaluated
// at the query point moved into its frame (to_node_frame) bounds the world irradiance.
#pragma once

#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

#include "lev/bounds.h"
#include "lev/light.h"
#include "lev/transform.h"

namespace lev {

struct LightAggregate {
  glm::vec3 intensity{0.0f};  // summed RGB intensity of the lights (an instance's scale^2 applied)
  Bounds positions;           // around every light position (padded for float rounding)
  // The spot axes lie within the angle acos(cos_axis_spread) of `axis` (pbrt-v4's theta_o).
  glm::vec3 axis{0.0f, 0.0f, 1.0f};
  float cos_axis_spread = 1.0f;
  // No light shines farther than acos(cos_emission) from its own axis (pbrt-v4's theta_e; a spot
  // with a dropoff is dark beyond 90 degrees). -1 when some light shines everywhere (a point
  // light, a spot of 180 degrees without dropoff): then the cone above says nothing.
  float cos_emission = -1.0f;
  float min_dropoff = 0.0f;  // the smallest Warn exponent P of the lights (0 with a point light)
};

inline bool is_empty(const LightAggregate& a) {
  return is_empty(a.positions);
}

// One light, in the frame its position is given in.
LightAggregate light_aggregate(const Light& light);
// The lights of both (the smallest cone around both cones, as pbrt-v4's DirectionCone Union).
LightAggregate merge_aggregates(const LightAggregate& a, const LightAggregate& b);
// The lights seen through xf (their frame's parent): moved, turned, intensity times scale^2.
LightAggregate transform_aggregate(const LightAggregate& a, const Similarity& xf);

// The query point in a node's frame, and how far float rounding may have moved it (and the
// lights the brute force computes in world space) from the exact point, in that frame's units.
// Every step of a transform rounds by a few float ulps of the magnitudes involved; kFrameRounding
// covers hundreds of them per step, so the allowance holds for hierarchies far deeper than the
// scene models (the property tests nest random similarities).
struct FramePoint {
  glm::vec3 point{0.0f};
  float rounding = 0.0f;
};
inline constexpr float kFrameRounding = 1e-4f;

inline float max_abs(const glm::vec3& v) {
  return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z));
}
// A world-space query point.
inline FramePoint world_frame_point(const glm::vec3& x) {
  return {x, kFrameRounding * max_abs(x)};
}
// The walk's point in a frame whose world_from_local has scale frame_scale and translation
// frame_origin: what rounding moved it by is bounded by the magnitudes of the world point
// (world_magnitude = max_abs of it) and of the frame's origin, measured in the frame's units.
inline FramePoint walk_frame_point(const glm::vec3& local_point, float world_magnitude,
                                   const glm::vec3& frame_origin, float frame_scale) {
  return {local_point, kFrameRounding * (world_magnitude + max_abs(frame_origin)) / frame_scale};
}
// The point seen from the child of an affine node with transform xf (parent_from_child).
inline FramePoint to_node_frame(const FramePoint& q, const Similarity& xf) {
  return {apply_inverse_point(xf, q.point),
          (q.rounding + kFrameRounding * (max_abs(q.point) + max_abs(xf.translation))) / xf.scale};
}
// The same for a pure translation t (the same floats, without the products by one).
inline FramePoint to_translated_frame(const FramePoint& q, const glm::vec3& t) {
  return {q.point - t, q.rounding + kFrameRounding * (max_abs(q.point) + max_abs(t))};
}

// A sum of bounds kept in double, as a float bound: rounded up, with room for the summation order
// (n terms in double round by at most n * 1.1e-16 relative, far below 1e-9 for any scene).
glm::vec3 round_up_sum(const glm::dvec3& sum);

// The largest cos(gamma)^P (Warn's factor, 1 for a point light) any light of the aggregate can
// have towards x, with x outside the box; 0 when x is outside every cone. gamma, the angle from a
// light's axis to x - p, is at least theta_w - theta_o - theta_b: the angle from the cone's axis
// to x - c (box centre), less the spread of the axes, less the angle the box subtends from x.
// Cosines and sines are combined without acos (as pbrt-v4's LightBounds::Importance), the sines
// from cross products so they stay accurate near 0 and pi.
// The bound of the sphere around the box is joined by a second one, by projection on the axis
// (cos_angle_bound_by_projection), which stays sharp where x is near the box or beside a flat one.
float spot_cone_factor(const LightAggregate& a, const FramePoint& x);

// An upper bound of cos(angle from the unit `axis` to x - p) over every p of the box with centre
// x - to_x and half extent `half`: the largest axis . (x - p) over the box, divided by the
// smallest |x - p| when it is positive and by the largest when it is not. 1 when x may lie in the
// box.
float cos_angle_bound_by_projection(const glm::vec3& axis, const glm::vec3& to_x,
                                    const glm::vec3& half);

inline bool shines_everywhere(const LightAggregate& a) {
  return a.cos_emission <= -1.0f;
}

// Relative room for the rounding of intensities, distances and 1/d^2 on both sides.
inline constexpr float kBoundMargin = 1.0f + 1e-4f;

// Upper bound of sum_i irradiance(light_i, x) (RGB) over the aggregate's lights at the point:
// +inf in a channel with light when x may lie in the box of the positions (a light may sit on
// x), 0 in a channel without light. Inline, with the spot cone out of line: the walk calls it for
// every subtree it culls.
inline glm::vec3 irradiance_bound(const LightAggregate& a, const FramePoint& x) {
  // The distance to the box grown by the rounding allowance on every side: a cube around the box
  // holds the ball around it, so this is at most the distance to the box less the allowance
  // (no square root needed). An empty aggregate's box is +inf away.
  const glm::vec3 zero(0.0f);
  const glm::vec3 gap = glm::max(
      glm::max(a.positions.lo - x.rounding - x.point, x.point - a.positions.hi - x.rounding), zero);
  const float gap2 = glm::dot(gap, gap);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  float falloff = gap2 > 0.0f ? kBoundMargin / gap2 : kInf;
  if (!shines_everywhere(a)) {
    const float factor = spot_cone_factor(a, x);
    if (factor == 0.0f) return zero;  // before the product: never inf * 0
    falloff *= factor;
  }
  if (falloff == 0.0f) return zero;  // far away: never 0 * an infinite intensity
  if (falloff == kInf) {
    return {a.intensity.x > 0.0f ? kInf : 0.0f, a.intensity.y > 0.0f ? kInf : 0.0f,
            a.intensity.z > 0.0f ? kInf : 0.0f};
  }
  return a.intensity * falloff;
}

// The surface's side of a cluster's bound (Walter et al. 2005, sec. 4.1, the material term):
// what the Phong response (thesis eq. 6 without the irradiance) of the shaded surface can be for
// light arriving from a box of positions. A ShadingPoint gives it (light_selector.h).
struct SurfaceResponse {
  // The unit normal on the lit side; zero when unknown (every direction may then be lit).
  glm::vec3 normal{0.0f};
  // The direction to the viewer mirrored about the normal (unit): the specular lobe's axis, as
  // Phong's cos(alpha) = mirror(l) . v = l . mirror(v).
  glm::vec3 mirrored_view{0.0f};
  glm::vec3 diffuse{0.0f};  // kd * colour
  float specular = 0.0f;    // ks
  float shininess = 1.0f;   // Phong exponent n
};

// The response to light from any direction toward any viewer: |kd * colour| + |ks| (cos(theta) and
// cos(alpha)^n are at most 1). Absolute values, so a negative coefficient cannot shrink it.
glm::vec3 largest_response(const SurfaceResponse& surface);

// An upper bound of the response to light from any position in `box` (in x's frame) at x: the
// diffuse term times the largest cos(theta) toward the box, the specular term times the largest
// cos(alpha)^n, both bounded by projection (cos_angle_bound_by_projection); zero when the whole
// box lies behind the surface. largest_response when the normal is unknown or x may lie in the box.
glm::vec3 response_bound(const SurfaceResponse& surface, const Bounds& box, const FramePoint& x);

// The bound of a cluster of lights at a surface point: the upper bound of the summed unshadowed
// radiance (RGB) its lights can add there, visibility taken as 1 (Walter et al. 2005, eq. 3): the
// aggregate's irradiance bound times the material's response bound over its box. One bound,
// used by every method that clusters (lightcuts' cut); the certified error bound takes the
// irradiance part and multiplies by largest_response. Never inf * 0: a channel without light or
// without response bounds nothing. When `irradiance` is given it receives that irradiance part
// (irradiance_bound's), computed once for both.
glm::vec3 radiance_bound(const LightAggregate& a, const FramePoint& x,
                         const SurfaceResponse& surface, glm::vec3* irradiance = nullptr);

}  // namespace lev
