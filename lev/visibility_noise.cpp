#include "lev/visibility_noise.h"

#include <cassert>
#include <cmath>

#include "lev/light.h"

namespace lev {

double visibility_noise(const std::vector<glm::vec3>& estimates,
                        const std::vector<std::uint8_t>& visible,
                        const std::vector<CutCluster>& centred_clusters,
                        const std::vector<std::size_t>& exact_clusters) {
  if (centred_clusters.empty() && exact_clusters.empty()) return 0.0;  // lights alone: exact
  assert(visible.size() == estimates.size());
  double unshadowed = 0.0;
  double found_visible = 0.0;
  double square_sum = 0.0;
  const auto add = [&](std::size_t i) {
    const double u = brightest(estimates[i]);
    if (!(u > 0.0)) return;
    unshadowed += u;
    if (visible[i] != 0) found_visible += u;
    square_sum += u * u;
  };
  for (const CutCluster& c : centred_clusters) add(c.index);
  for (const std::size_t i : exact_clusters) add(i);
  if (!(unshadowed > 0.0)) return 0.0;
  const double p = found_visible / unshadowed;
  return std::sqrt(p * (1.0 - p) * square_sum);
}

}  // namespace lev
