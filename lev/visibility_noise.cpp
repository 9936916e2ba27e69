#include "lev/visibility_noise.h"

#include <cassert>
#include <cmath>

#include "lev/light.h"

namespace lev {

double visibility_noise(const std::vector<glm::vec3>& estimates,
                        const std::vector<std::uint8_t>& visible,
                        const std::vector<std::size_t>& clusters) {
  if (clusters.empty()) return 0.0;  // lights alone: exact
  assert(visible.size() == estimates.size());
  double unshadowed = 0.0;
  double found_visible = 0.0;
  double square_sum = 0.0;
  for (const std::size_t i : clusters) {
    const double u = brightest(estimates[i]);
    if (!(u > 0.0)) continue;
    unshadowed += u;
    if (visible[i] != 0) found_visible += u;
    square_sum += u * u;
  }
  if (!(unshadowed > 0.0)) return 0.0;
  const double p = found_visible / unshadowed;
  return std::sqrt(p * (1.0 - p) * square_sum);
}

CutTotals cut_totals(const std::vector<glm::vec3>& estimates,
                     const std::vector<std::uint8_t>& visible) {
  assert(visible.size() == estimates.size());
  glm::dvec3 unshadowed(0.0);
  glm::dvec3 found_visible(0.0);
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    unshadowed += glm::dvec3(estimates[i]);
    if (visible[i] != 0) found_visible += glm::dvec3(estimates[i]);
  }
  return {brightest(unshadowed), brightest(found_visible)};
}

}  // namespace lev
