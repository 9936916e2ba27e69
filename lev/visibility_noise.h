// The noise of a relative cut's shadow rays at one point, as its rays found it: each cluster of
// several lights is shaded through one 0/1 shadow ray, so where some of its lights are hidden and
// some are not the ray gives all of the cluster's light or none of it. Summed over the clusters
// that noise is what bounds lev_cut's maximum pixel error where hundreds of partly hidden clusters
// light a point (the halls' rig: docs/results/lev_cut.md), and a finer cut shrinks it only where
// it is spent. visibility_noise estimates it from the rays just cast, so that lev_cut refines the
// cut at those points alone (selector_lev_cut.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lev {

// The standard deviation (brightest channel, radiance units) of the summed visible radiance of a
// cut's clusters whose one ray stands for several lights: sqrt(p (1 - p) sum_c u_c^2) over those
// clusters, where u_c is a cluster's unshadowed estimate and p the share of their summed
// estimates the rays found visible (pooled over the clusters: one ray says nothing of its own
// cluster's share). Binomial noise of independent 0/1 rays with that share. `estimates` and
// `visible` are per entry of the cut (WalkScratch::cut_estimates; the shading loop's outcome, 1
// where a ray found its light); `clusters` are the entries that are such clusters
// (WalkScratch::several_light_clusters). A ray to a single light (or to the one lit light of a
// cluster) is exact and carries no such noise, so a cut of lights alone gives 0.
double visibility_noise(const std::vector<glm::vec3>& estimates,
                        const std::vector<std::uint8_t>& visible,
                        const std::vector<std::size_t>& clusters);

// A cut's summed estimates (brightest channel, radiance units): all of them, the running total
// the cut was made relative to, and those whose rays found their lights. The cut assumes every
// light visible; where the rays hide most of that total (a huge light behind a wall), the pixel
// is the visible part, and the cut's clusters were judged against a total it does not show.
struct CutTotals {
  double unshadowed = 0.0;
  double visible = 0.0;
};
CutTotals cut_totals(const std::vector<glm::vec3>& estimates,
                     const std::vector<std::uint8_t>& visible);

}  // namespace lev
