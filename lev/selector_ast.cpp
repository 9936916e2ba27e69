#include "lev/selector_ast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lev/important_lights.h"
#include "lev/light_bounds.h"

namespace lev {

AstSelector::AstSelector(const LightHierarchy& hierarchy, float tolerance)
    : tolerance_(tolerance),
      world_lights_(flatten_lights(hierarchy)),
      hits_(world_lights_.size(), 0),
      tests_(world_lights_.size(), 0),
      pass_hits_(new std::atomic<std::uint32_t>[world_lights_.size()]),
      pass_tests_(new std::atomic<std::uint32_t>[world_lights_.size()]) {
  for (std::size_t i = 0; i < world_lights_.size(); ++i) {
    pass_hits_[i].store(0, std::memory_order_relaxed);
    pass_tests_[i].store(0, std::memory_order_relaxed);
  }
}

glm::vec3 AstSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                       SelectionCounters& counters,
                                       glm::vec3* culled_irradiance_bound) const {
  const glm::vec3 x = point.position();
  // Unknown until the end (a cancelled call returns early, with a result the caller discards).
  if (culled_irradiance_bound)
    *culled_irradiance_bound = glm::vec3(std::numeric_limits<float>::infinity());
  // Both loops run over every light (a million shadow rays per point at tolerance 0): like
  // sum_visible_lights they read the cancel flag every kCancelCheckLights lights and return early,
  // a result the caller discards.
  const std::atomic<bool>* cancel = scratch.cancel;
  const auto cancelled = [cancel](std::size_t count) {
    return cancel && count % kCancelCheckLights == 0 && cancel->load(std::memory_order_relaxed);
  };
  // Step 1 of thesis fig. 2.8: the potential contribution of every light in front of the point.
  std::vector<AstCandidate>& heap = method_scratch<AstScratch>(scratch).candidates;
  heap.clear();
  double untested = 0.0;
  // The scan is rt's (sum_visible_lights): the count, the lights and the inspector's record in
  // locals, which the compiler cannot keep there itself across the calls below. Read through the
  // members, ast's scan took more instructions than rt's whole loop where few lights pass
  // (street_bare 16,384 at tolerance 1, no shadow ray: 282 M against rt's 248 M; now 239 M).
  InspectRecord* const record = scratch.inspect;
  const Light* const lights = world_lights_.data();
  const auto light_count = static_cast<std::uint32_t>(world_lights_.size());
  for (std::uint32_t i = 0; i < light_count; ++i) {
    if (cancelled(i + 1)) return glm::vec3(0.0f);
    const Light& light = lights[i];
    if (!is_important(light, x, 0.0f)) {
      if (record) record->culled_lights.push_back(light);
      continue;
    }
    const glm::vec3 radiance = point.unshadowed_radiance(light);
    const float potential = brightest(radiance);
    if (potential <= 0.0f) {
      if (record) record->culled_lights.push_back(light);
      continue;
    }
    heap.push_back({potential, i, radiance});
    untested += potential;
  }
  // Step 2: order them. Instead of a full sort, a heap yields the largest contributions in
  // order; the test loop usually stops long before the heap is empty. Ties break on the light index
  // so the order is a pure function of the inputs.
  auto smaller = [](const AstCandidate& a, const AstCandidate& b) {
    return a.potential < b.potential || (a.potential == b.potential && a.light > b.light);
  };
  std::make_heap(heap.begin(), heap.end(), smaller);
  std::size_t remaining = heap.size();
  // Steps 3 and 4: test the largest until the untested rest is below the tolerance (which
  // stands in for step 3's certainty sums r(i)). The sum is a float running sum, unlike the
  // double one of sum_visible_lights: usually it adds a few large terms, where float drifts
  // little, and ast's images are defined by it (a double sum would change them).
  // The running rest is a difference of sums, which a huge potential swamps: after 1e36 + 0.3 +
  // 0.3 less 1e36 it says 0 (or less, after one more 0.3) while 0.6 is untested, and testing
  // stopped there, at tolerance 0 too. Every partial sum is at most the first one and each
  // operation rounds by at most its epsilon, so where the running rest is within that slack of
  // the tolerance the rest is summed again from the candidates left.
  const double epsilon = std::numeric_limits<double>::epsilon();
  double slack = static_cast<double>(heap.size()) * untested * epsilon;
  const auto rest_below_tolerance = [&]() {
    if (untested >= tolerance_) return false;
    if (untested + slack < tolerance_) return true;
    untested = 0.0;
    for (std::size_t k = 0; k < remaining; ++k) untested += heap[k].potential;
    slack = static_cast<double>(remaining) * untested * epsilon;
    return untested < tolerance_;
  };
  glm::vec3 sum(0.0f);
  std::uint32_t point_hits = 0, point_tests = 0;
  while (remaining > 0 && !rest_below_tolerance()) {
    std::pop_heap(heap.begin(), heap.begin() + static_cast<std::ptrdiff_t>(remaining), smaller);
    --remaining;
    const AstCandidate& c = heap[remaining];
    untested -= c.potential;
    slack += std::abs(untested) * epsilon;
    ++point_tests;
    if (cancelled(point_tests)) return sum;
    ++counters.lights_tested;
    ++counters.shadow_rays;
    pass_tests_[c.light].fetch_add(1, std::memory_order_relaxed);
    const bool visible = point.visible(world_lights_[c.light]);
    if (scratch.inspect) {
      ShadedLight& shaded = scratch.inspect->shaded.emplace_back();
      shaded.light = world_lights_[c.light];
      shaded.unshadowed_radiance = c.radiance;
      shaded.shadow_ray = true;
      shaded.visible = visible;
      if (visible) shaded.contribution = c.radiance;
    }
    if (visible) {
      ++point_hits;
      pass_hits_[c.light].fetch_add(1, std::memory_order_relaxed);
      sum += c.radiance;
    }
  }
  // Step 5: estimate the untested rest from visibility statistics.
  const float point_ratio = point_tests > 0 ? static_cast<float>(point_hits) / point_tests : 1.0f;
  const auto estimated_ratio = [&](std::uint32_t light) {
    return tests_[light] > 0 ? static_cast<float>(hits_[light]) / static_cast<float>(tests_[light])
                             : point_ratio;
  };
  for (std::size_t k = 0; k < remaining; ++k) {
    const AstCandidate& c = heap[k];
    const float ratio = estimated_ratio(c.light);
    sum += c.radiance * ratio;
    if (scratch.inspect) {
      ShadedLight& shaded = scratch.inspect->shaded.emplace_back();
      shaded.light = world_lights_[c.light];
      shaded.role = InspectRole::estimated;
      shaded.unshadowed_radiance = c.radiance;
      shaded.weight = ratio;
      shaded.contribution = c.radiance * ratio;
    }
  }
  // The estimated rest is off by at most its unshadowed value: its irradiance bounds the error.
  // At the surface itself, a light estimated at `ratio` of its unshadowed radiance R is off by
  // R * max(ratio, 1 - ratio) at most, whether it is seen (1) or not (0).
  if (culled_irradiance_bound) {
    glm::dvec3 rest(0.0), rest_radiance(0.0);
    for (std::size_t k = 0; k < remaining; ++k) {
      const AstCandidate& c = heap[k];
      rest += glm::dvec3(irradiance(world_lights_[c.light], x));
      const float ratio = estimated_ratio(c.light);
      rest_radiance += glm::dvec3(c.radiance) * static_cast<double>(std::max(ratio, 1.0f - ratio));
    }
    *culled_irradiance_bound = round_up_sum(rest);
    if (scratch.culled_radiance) {
      scratch.culled_radiance->bound = round_up_sum(rest_radiance);
      scratch.culled_radiance->bounded = true;
    }
  }
  // Clamped to the largest float as sum_visible_lights' sum is: a float sum of huge terms
  // overflows to +inf.
  return glm::min(sum, glm::vec3(std::numeric_limits<float>::max()));
}

void AstSelector::end_pass() {
  for (std::size_t i = 0; i < world_lights_.size(); ++i) {
    hits_[i] += pass_hits_[i].exchange(0, std::memory_order_relaxed);
    tests_[i] += pass_tests_[i].exchange(0, std::memory_order_relaxed);
  }
}

std::size_t AstSelector::bookkeeping_bytes() const {
  return world_lights_.size() * (sizeof(Light) + 4 * sizeof(std::uint32_t));
}

}  // namespace lev
