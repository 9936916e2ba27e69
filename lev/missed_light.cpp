#include "lev/missed_light.h"

#include <algorithm>

namespace lev {

void estimate_missed_light(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                           float tolerance, ShadingPoint& point, SelectorScratch& scratch,
                           const glm::vec3& stand_in) {
  MissedLight* missed = scratch.missed;
  if (!missed) return;
  if (!scratch.missed_scratch) scratch.missed_scratch = std::make_unique<MissedScratch>();
  MissedScratch& own = static_cast<MissedScratch&>(*scratch.missed_scratch);
  own.found.clear();
  WalkCounters walk_counters;
  find_important_and_culled(hierarchy, volumes, tolerance, point.position(), scratch.walk,
                            own.found, walk_counters, own.sampling.parts);
  missed->estimated = true;
  glm::dvec3 mean(0.0), square_sum(0.0);
  if (!own.sampling.parts.subtrees.empty() || !own.sampling.parts.lights.empty()) {
    SelectionCounters counters;  // the estimate's own work: not the method's
    mean = glm::dvec3(sampled_radiance(hierarchy, missed->draws, point, *missed->random,
                                       own.sampling, counters, &square_sum));
  }
  const double k = static_cast<double>(missed->draws);
  // The variance of the mean of k draws: the draws' sample variance over k.
  const glm::dvec3 variance =
      glm::max((square_sum / k - mean * mean) * (k / (k - 1.0)), glm::dvec3(0.0)) / k;
  missed->radiance = glm::vec3(mean) - stand_in;
  missed->variance = glm::vec3(variance);
}

glm::vec3 visible_radiance_below_tolerance(const std::vector<Light>& lights, float tolerance,
                                           ShadingPoint& point) {
  const glm::vec3 x = point.position();
  SelectionCounters counters;
  return sum_visible_lights(
      lights, [&](const Light& light) { return !is_important(light, x, tolerance); }, point,
      counters);
}

}  // namespace lev
