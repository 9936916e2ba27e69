#include "renderer/pixel_inspection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace renderer {
namespace {

double largest_magnitude(const glm::dvec3& v) {
  if (std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z))
    return std::numeric_limits<double>::quiet_NaN();
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// -1 when `a` goes first (the larger), 1 when `b` does, 0 for a tie; NaN after every number.
int compare_descending(double a, double b) {
  const bool a_nan = std::isnan(a), b_nan = std::isnan(b);
  if (a_nan || b_nan) return a_nan == b_nan ? 0 : (a_nan ? 1 : -1);
  if (a > b) return -1;
  if (a < b) return 1;
  return 0;
}

}  // namespace

ContributionRank contribution_rank(const glm::dvec3& to_pixel, const glm::dvec3& unshadowed,
                                   std::size_t order) {
  return {largest_magnitude(to_pixel), largest_magnitude(unshadowed), order};
}

bool ranks_before(const ContributionRank& a, const ContributionRank& b) {
  if (const int c = compare_descending(a.to_pixel, b.to_pixel)) return c < 0;
  if (const int c = compare_descending(a.unshadowed, b.unshadowed)) return c < 0;
  return a.order < b.order;
}

InspectedTotals hit_totals(const InspectedHit& hit) {
  InspectedTotals t;
  const double weight = hit.path_weight;
  glm::dvec3 exact(0.0);
  for (const lev::ShadedLight& shaded : hit.record.shaded) {
    ++t.shaded;
    if (shaded.role == lev::InspectRole::tested) {
      ++t.tested_lights;
      exact += glm::dvec3(shaded.visible ? shaded.unshadowed_radiance : glm::vec3(0.0f));
    }
    if (shaded.role == lev::InspectRole::cluster || shaded.role == lev::InspectRole::estimated) {
      ++t.clusters;
      t.clustered_lights += shaded.members.size();
      for (const lev::InspectedLight& member : shaded.members)
        exact += glm::dvec3(member.visible_radiance());
    }
  }
  // AST's estimates are not shaded terms the render counts as tested.
  for (const lev::ShadedLight& shaded : hit.record.shaded) {
    if (shaded.role == lev::InspectRole::estimated) --t.shaded;
  }
  for (const lev::InspectedLight& culled : hit.record.culled) {
    ++t.culled_lights;
    exact += glm::dvec3(culled.visible_radiance());
  }
  t.tested = weight * glm::dvec3(hit.direct_radiance);
  t.exact = weight * exact;
  t.lost = t.exact - t.tested;
  t.bound = glm::dvec3(hit.error_bound);
  return t;
}

PixelInspection inspect_pixel(const Scene& scene, const RayScene& rays,
                              const RenderSettings& settings, const lev::LightSelector& selector,
                              int x, int y, const std::atomic<bool>* cancel) {
  if (x < 0 || y < 0 || x >= settings.width || y >= settings.height) {
    throw std::invalid_argument("inspect: pixel " + std::to_string(x) + "," + std::to_string(y) +
                                " outside the " + std::to_string(settings.width) + "x" +
                                std::to_string(settings.height) + " image");
  }
  PixelInspection inspection;
  inspection.x = x;
  inspection.y = y;
  lev::SelectorScratch scratch;
  scratch.cancel = cancel;
  TraceContext context{scene, rays, selector, scratch, settings.max_depth, nullptr, cancel, true};
  context.inspection = &inspection.hits;
  const Ray ray =
      pixel_sample_ray(settings, scene.camera, x, y, 0, scratch.random, context.missed_random);
  inspection.radiance = clamp_sample_radiance(trace_radiance(context, ray, 0, inspection.counters));
  for (const InspectedHit& hit : inspection.hits) {
    const InspectedTotals t = hit_totals(hit);
    InspectedTotals& all = inspection.totals;
    all.tested += t.tested;
    all.exact += t.exact;
    all.lost += t.lost;
    all.bound += t.bound;
    all.shaded += t.shaded;
    all.tested_lights += t.tested_lights;
    all.culled_lights += t.culled_lights;
    all.clusters += t.clusters;
    all.clustered_lights += t.clustered_lights;
  }
  return inspection;
}

}  // namespace renderer
