#include "lev/selector_lev_est.h"

#include <algorithm>

#include "lev/missed_light.h"

namespace lev {

namespace {

// Where the culled rest is cut into clusters, in multiples of the tolerance (the scale of the
// per-light test). Measured on hall 4,096 at tolerance 0.01 (160x120, errors against rt, with
// the representative at the centre of its cluster): refining every culled part above 2, 3, 4,
// 8, 16 x tolerance gives avg/max errors 0.14/2.5, 0.17/5.1, 0.19/4.8, 0.29/7.6, 0.38/11.4 %
// with 7.6, 5.7, 4.5, 2.1, 1.4 M shadow rays (rt: 46.6 M). 4 is the coarsest cut within the
// issue's targets (avg < 1 %, max < 5 %). Parts at most a quarter of the tolerance are left out
// (summed in the bound only): keeping them all changed no pixel there.
constexpr float kRefineAboveTolerances = 4.0f;
constexpr float kKeepAboveTolerances = 0.25f;
// The rest is estimated only where it may matter: where the culled bound exceeds this share of
// the irradiance the tested lights deliver through their shadow rays (visible ones only: a point
// whose tested lights are all occluded is lit by the rest alone). Measured at tolerance 0.01,
// 160x120, avg/max error against rt, share 10 / 1 / 0.1:
//   hall 1,024:   1.34 / 20.4 % at 1, 0.17 / 5.0 % at 0.1 (lev: 8.19 / 21.6 %);
//   hall 4,096:   0.49 / 47.6, 0.20 / 5.0, 0.20 / 5.0 %; maze 3,069: 0.42 / 3.9, 0.15 / 3.4,
//   0.08 / 1.3 % (lev: 0.43 / 3.9 %).
// A share above 1 relied on the bound being loose: with the spot cone bounded by projection
// (light_bounds.h) it is close enough that 10 left hall points at half their light. The price
// of 0.1 is where lev is already exact and the rest sits behind walls: building 4,096 casts
// 135 shadow rays a point instead of lev's 30 (0.21 s a pass against lev's 0.05 and rt's 3.45).
constexpr float kRestShareOfSeen = 0.1f;
// That share shrinks with the tolerance below kShareFromTolerance: a fixed share made lev_est
// worse as its tolerance tightened (hall 16,384, 80x60: max error 1.05 % at 0.001, 3.92 % at
// 0.0003), because more lights tested let the gate skip a rest still worth a tenth of them.
// With the share proportional to the tolerance the rest left unestimated shrinks with it.
constexpr float kShareFromTolerance = 0.01f;

// The share of the seen irradiance above which the culled rest is estimated, at `tolerance`.
float rest_share_of_seen(float tolerance) {
  return kRestShareOfSeen * std::min(1.0f, tolerance / kShareFromTolerance);
}

ClusterCut cut_for(float tolerance, float display_scale) {
  ClusterCut cut;
  cut.refine_above = kRefineAboveTolerances * tolerance;
  cut.keep_above = kKeepAboveTolerances * tolerance;
  cut.rest_share_of_seen = rest_share_of_seen(tolerance * display_scale);
  return cut;
}

}  // namespace

LevEstSelector::LevEstSelector(const LightHierarchy& hierarchy, float tolerance,
                               float display_scale)
    : hierarchy_(hierarchy),
      volumes_(fit_extent_volumes(hierarchy, tolerance)),
      tolerance_(tolerance),
      cut_(cut_for(tolerance, display_scale)) {}

// The estimate of the culled rest, chosen by measurement (hall 4,096, tolerance 0.01, cut as
// above; avg/max error against rt):
//   - Lightcuts' representative with one shadow ray per cluster, the representative being the
//     cluster's first light: 0.69 / 6.7 %; its light nearest the centre of the cluster's box:
//     0.41 / 7.1 %; a light at the centre itself, aimed along the cluster's cone axis (kept):
//     0.19 / 4.8 % (16,384 lights: 0.19 / 5.9 %). The centre cancels the first-order error of
//     distance and spot angle that a corner light makes the same way in every cluster.
//   - Ward's hit ratio (AST, thesis 6.5): the clusters' unshadowed radiance times the share of
//     tested lights found visible at the point, no ray per cluster: 1.46 / 27.7 % (most hall
//     points test no light, so the robots cast no shadow), and on maze 3,069 0.47 / 5.9 %,
//     worse than lev's 0.43 / 3.9 %, as light behind a corridor wall is counted as seen.
glm::vec3 LevEstSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                          SelectionCounters& counters,
                                          glm::vec3* culled_irradiance_bound) const {
  std::vector<Light>& clusters = method_scratch<LevEstScratch>(scratch).clusters;
  const glm::vec3 x = point.position();
  scratch.lights.clear();
  clusters.clear();
  WalkCounters walk_counters;
  glm::vec3 culled_bound;
  find_important_lights(hierarchy_, volumes_, tolerance_, x, scratch.walk, scratch.lights,
                        walk_counters, &culled_bound);
  // The tested lights first: the gate below weighs the rest against what of them is seen.
  float visible_tested_irradiance = 0.0f;
  const glm::vec3 tested = sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, point, counters, scratch.cancel,
      &visible_tested_irradiance, scratch.inspect);
  const float culled = brightest(culled_bound);
  if (culled > cut_.keep_above && culled > cut_.rest_share_of_seen * visible_tested_irradiance) {
    // The same walk again, now cutting what it culls into clusters: it returns the same lights,
    // already summed above.
    scratch.lights.clear();
    if (scratch.inspect) scratch.inspect->clear_walk();
    find_lights_and_clusters(hierarchy_, volumes_, tolerance_, cut_, x, scratch.walk,
                             scratch.lights, clusters, walk_counters, &culled_bound);
  }
  counters.nodes_visited += walk_counters.nodes_visited;
  // The estimate is not exact, so the bound still counts every culled cluster.
  if (culled_irradiance_bound) *culled_irradiance_bound = culled_bound;
  const std::size_t clusters_from = scratch.inspect ? scratch.inspect->shaded.size() : 0;
  glm::vec3 estimate = sum_visible_lights(
      clusters, [](const Light&) { return true; }, point, counters, scratch.cancel, nullptr,
      scratch.inspect);
  if (scratch.inspect) scratch.inspect->attach_walk_clusters(clusters_from);
  // The clusters' estimate E stands for what lev culls, whose shadowed radiance C lies in
  // [0, lev's culled radiance bound R] per channel: E above R is wrong by more than min(E, R) is,
  // so it is taken down to R. A representative sits at its cluster's centre, which may lie next
  // to the point while every light of the cluster is far: seen there, it stood for 0.67 (white at
  // the pixel) where R was 0.2 and the lights were all hidden. R costs one more walk, made only
  // where clusters were cut (or where the bound is asked).
  CulledRadianceBound culled_radiance;
  const bool radiance_bound_asked = scratch.culled_radiance && culled_irradiance_bound;
  if (!clusters.empty() || radiance_bound_asked) {
    culled_radiance = lev_culled_radiance_bound(
        hierarchy_, volumes_, tolerance_, x, point.surface_response(), scratch.walk,
        method_scratch<LevEstScratch>(scratch).bound_lights);
    if (culled_radiance.bounded) {
      const glm::vec3 bounded = glm::min(estimate, culled_radiance.bound);
      // The inspector's cluster rows add up to the pixel as shaded: each scaled alike.
      if (scratch.inspect && bounded != estimate) {
        for (std::size_t i = clusters_from; i < scratch.inspect->shaded.size(); ++i) {
          glm::vec3& contribution = scratch.inspect->shaded[i].contribution;
          for (int c = 0; c < 3; ++c)
            if (estimate[c] > 0.0f) contribution[c] *= bounded[c] / estimate[c];
        }
      }
      estimate = bounded;
    }
  }
  // The radiance error at the surface: |E - C| is at most max(E, R).
  if (radiance_bound_asked) {
    culled_radiance.bound = glm::max(culled_radiance.bound, estimate);
    *scratch.culled_radiance = culled_radiance;
  }
  // What lev culls, less the clusters' estimate that stood in for it.
  estimate_missed_light(hierarchy_, volumes_, tolerance_, point, scratch, estimate);
  return tested + estimate;
}

}  // namespace lev
