#include "lev/light_bounds.h"

#include <cmath>

namespace lev {
namespace {

// Every stored cone is widened by this angle (and its cosine rounded down): the walk turns the
// spot axes with float matrices, a few 1e-7 radians from the double arithmetic here.
constexpr double kAngleSlack = 1e-6;
// Boxes grow by this relative margin per step, like the extent volumes (light_hierarchy.cpp).
constexpr float kPositionPadding = 1e-5f;
// The float arithmetic of irradiance_bound and of the exact test (cos(gamma) in is_important)
// each round by a few 1e-7 in a cosine; cones are compared with this much room.
constexpr float kCosSlack = 1e-5f;

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  // atan2 of |a x b| and a.b is accurate at every angle (acos of the dot is not near 0 and pi).
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The cone's cosine as stored: the angle widened by kAngleSlack, the cosine rounded down.
float stored_cos(double angle) {
  if (angle + kAngleSlack >= M_PI) return -1.0f;
  return std::max(-1.0f, round_outwards(std::cos(angle + kAngleSlack), -1));
}

double stored_angle(float cos_angle) {
  return std::acos(std::clamp(static_cast<double>(cos_angle), -1.0, 1.0));
}

// Rotation of v about the unit axis k by angle (Rodrigues).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

glm::vec3 sum_rounded_up(const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 r;
  for (int i = 0; i < 3; ++i)
    r[i] = round_outwards(static_cast<double>(a[i]) + static_cast<double>(b[i]), +1);
  return r;
}

}  // namespace

LightAggregate light_aggregate(const Light& light) {
  LightAggregate a;
  a.intensity = light.intensity;
  a.positions = pad_bounds({light.position, light.position}, kPositionPadding);
  if (light.kind == LightKind::point) return a;
  a.axis = glm::vec3(glm::normalize(glm::dvec3(light.direction)));
  a.cos_axis_spread = stored_cos(0.0);
  // A smooth (glTF) spot ignores its dropoff: its ramp reaches 1 anywhere inside the inner cone,
  // so only the hard outer cone bounds it, as a spot without a dropoff.
  const float dropoff = light.profile == SpotProfile::smooth ? 0.0f : light.dropoff;
  a.min_dropoff = dropoff;
  // With a dropoff, cos(gamma)^P is zero from 90 degrees on (light.h).
  a.cos_emission =
      dropoff > 0.0f ? std::max(light.cos_cone_half_angle, 0.0f) : light.cos_cone_half_angle;
  return a;
}

LightAggregate merge_aggregates(const LightAggregate& a, const LightAggregate& b) {
  if (is_empty(a)) return b;
  if (is_empty(b)) return a;
  LightAggregate m;
  m.intensity = sum_rounded_up(a.intensity, b.intensity);
  m.positions = merge(a.positions, b.positions);
  m.min_dropoff = std::min(a.min_dropoff, b.min_dropoff);
  m.cos_emission = std::min(a.cos_emission, b.cos_emission);
  if (shines_everywhere(m)) return m;
  // The smallest cone holding both axis cones (pbrt-v4 DirectionCone Union).
  const glm::dvec3 wa(a.axis), wb(b.axis);
  const double theta_a = stored_angle(a.cos_axis_spread), theta_b = stored_angle(b.cos_axis_spread);
  const double theta_d = angle_between(wa, wb);
  if (std::min(theta_d + theta_b, M_PI) <= theta_a) {
    m.axis = a.axis;
    m.cos_axis_spread = a.cos_axis_spread;
    return m;
  }
  if (std::min(theta_d + theta_a, M_PI) <= theta_b) {
    m.axis = b.axis;
    m.cos_axis_spread = b.cos_axis_spread;
    return m;
  }
  const double theta_o = 0.5 * (theta_a + theta_d + theta_b);
  const glm::dvec3 turn_axis = glm::cross(wa, wb);
  if (theta_o >= M_PI || glm::dot(turn_axis, turn_axis) == 0.0) {
    m.cos_axis_spread = -1.0f;  // every direction
    return m;
  }
  m.axis = glm::vec3(glm::normalize(rotate(wa, glm::normalize(turn_axis), theta_o - theta_a)));
  m.cos_axis_spread = stored_cos(theta_o);
  return m;
}

LightAggregate transform_aggregate(const LightAggregate& a, const Similarity& xf) {
  if (is_empty(a)) return a;
  LightAggregate t = a;
  const double scale2 = static_cast<double>(xf.scale) * static_cast<double>(xf.scale);
  for (int i = 0; i < 3; ++i)
    t.intensity[i] = round_outwards(static_cast<double>(a.intensity[i]) * scale2, +1);
  t.positions = pad_bounds(transform_bounds(a.positions, xf), kPositionPadding);
  if (!shines_everywhere(a) && a.cos_axis_spread > -1.0f) {
    t.axis = glm::vec3(glm::normalize(glm::dmat3(xf.rotation) * glm::dvec3(a.axis)));
    t.cos_axis_spread = stored_cos(stored_angle(a.cos_axis_spread));
  }
  return t;
}

glm::vec3 round_up_sum(const glm::dvec3& sum) {
  const glm::dvec3 total = sum * (1.0 + 1e-9);
  return {round_outwards(total.x, +1), round_outwards(total.y, +1), round_outwards(total.z, +1)};
}

float spot_cone_factor(const LightAggregate& a, const FramePoint& x) {
  const glm::vec3 centre = 0.5f * (a.positions.lo + a.positions.hi);
  const glm::vec3 half = 0.5f * (a.positions.hi - a.positions.lo) + x.rounding;
  const glm::vec3 to_x = x.point - centre;
  const float cos_o = a.cos_axis_spread;
  const float sin_o = std::sqrt(std::max(0.0f, (1.0f - cos_o) * (1.0f + cos_o)));
  // Two lower bounds of theta_w - theta_b, the smallest angle from the cone's axis to x - p over
  // the box; the larger one counts. The sphere's (pbrt-v4) is sharp far from a compact box; the
  // projection's below is sharp near a box and beside a flat one (a row of ceiling spots seen
  // from their own height), where the sphere around the box holds x and says nothing.
  float cos_w = 1.0f, sin_w = 0.0f;
  const float radius = glm::length(half);
  const float distance = glm::length(to_x);
  if (distance > radius) {
    const float sin_b = radius / distance;
    const float cos_b = std::sqrt((1.0f - sin_b) * (1.0f + sin_b));
    const float cos_c = glm::dot(a.axis, to_x) / distance;
    const float sin_c = glm::length(glm::cross(a.axis, to_x)) / distance;
    if (cos_c < cos_b) {
      cos_w = cos_c * cos_b + sin_c * sin_b;
      sin_w = std::max(0.0f, sin_c * cos_b - cos_c * sin_b);
    }
  }
  const float cos_p = cos_angle_bound_by_projection(a.axis, to_x, half) + kCosSlack;
  if (cos_p < cos_w) {
    cos_w = std::max(-1.0f, cos_p);
    sin_w = std::sqrt((1.0f - cos_w) * (1.0f + cos_w));
  }
  // theta_y = max(0, theta_w - theta_o): the smallest angle from a light's own axis to x - p.
  float cos_y = 1.0f;
  if (cos_w < cos_o) cos_y = cos_w * cos_o + sin_w * sin_o;
  if (cos_y + kCosSlack < a.cos_emission) return 0.0f;
  if (a.min_dropoff > 0.0f) {
    // Every spot has a dropoff: dark from 90 degrees on; with P >= 1, cos^P <= cos.
    if (cos_y + kCosSlack <= 0.0f) return 0.0f;
    if (a.min_dropoff >= 1.0f) return std::min(1.0f, cos_y + kCosSlack);
  }
  return 1.0f;
}

glm::vec3 largest_response(const SurfaceResponse& surface) {
  return glm::abs(surface.diffuse) + glm::vec3(std::abs(surface.specular));
}

glm::vec3 response_bound(const SurfaceResponse& surface, const Bounds& box, const FramePoint& x) {
  if (surface.normal == glm::vec3(0.0f)) return largest_response(surface);
  const glm::vec3 centre = 0.5f * (box.lo + box.hi);
  const glm::vec3 half = 0.5f * (box.hi - box.lo) + x.rounding;
  const glm::vec3 to_x = x.point - centre;
  // cos(theta) = n . l with l = (p - x) / |p - x|: the cosine from -n to x - p.
  const float cos_theta = cos_angle_bound_by_projection(-surface.normal, to_x, half) + kCosSlack;
  if (cos_theta <= 0.0f) return glm::vec3(0.0f);  // shading.cpp's response is zero there
  glm::vec3 bound = glm::abs(surface.diffuse) * std::min(1.0f, cos_theta);
  if (surface.specular != 0.0f) {
    const float cos_alpha = std::min(
        1.0f, cos_angle_bound_by_projection(-surface.mirrored_view, to_x, half) + kCosSlack);
    // cos^n grows toward 1 as cos does for n >= 0; a negative n is bounded by nothing smaller.
    const float lobe = surface.shininess < 0.0f ? std::numeric_limits<float>::infinity()
                       : cos_alpha > 0.0f       ? std::pow(cos_alpha, surface.shininess)
                                                : 0.0f;
    bound += glm::vec3(std::abs(surface.specular) * lobe);
  }
  return bound;
}

glm::vec3 radiance_bound(const LightAggregate& a, const FramePoint& x,
                         const SurfaceResponse& surface, glm::vec3* irradiance_part) {
  const glm::vec3 irradiance = irradiance_bound(a, x);
  if (irradiance_part) *irradiance_part = irradiance;
  if (irradiance == glm::vec3(0.0f)) return irradiance;
  const glm::vec3 response = response_bound(surface, a.positions, x);
  glm::vec3 bound(0.0f);
  for (int c = 0; c < 3; ++c) {
    if (irradiance[c] > 0.0f && response[c] > 0.0f) bound[c] = irradiance[c] * response[c];
  }
  return bound;
}

float cos_angle_bound_by_projection(const glm::vec3& axis, const glm::vec3& to_x,
                                    const glm::vec3& half) {
  // Over the box, axis . (x - p) is at most `along`, and |x - p| lies between the distance to the
  // box and the distance to its farthest corner: cos = along / |x - p| is at most along over the
  // smaller one when along is positive, over the larger one when it is not.
  // The float arithmetic of the dot products and the distances rounds by a few 1e-7 of the
  // magnitudes involved; `slack` covers far more, on the safe side of both.
  const float slack = 1e-5f * (max_abs(to_x) + max_abs(half));
  const float along = glm::dot(axis, to_x) + glm::dot(glm::abs(axis), half) + slack;
  if (along > 0.0f) {
    const float nearest = glm::length(glm::max(glm::abs(to_x) - half, glm::vec3(0.0f))) - slack;
    return along < nearest ? along / nearest : 1.0f;
  }
  return std::max(-1.0f, along / glm::length(glm::abs(to_x) + half));
}

}  // namespace lev
