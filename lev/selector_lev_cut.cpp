#include "lev/selector_lev_cut.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstring>
#include <limits>

#include "lev/visibility_noise.h"

namespace lev {

LevCutSelector::LevCutSelector(const LightHierarchy& hierarchy, float relative_error,
                               float display_scale, double noise_sigmas)
    : hierarchy_(hierarchy),
      relative_error_(relative_error),
      display_scale_(display_scale),
      noise_sigmas_(noise_sigmas),
      tolerance_(relative_error * kDropToleranceOfRelativeError / display_scale),
      volumes_(fit_extent_volumes(hierarchy, tolerance_)),
      cut_nodes_(make_cut_node_table(hierarchy)) {}

namespace {

bool earlier_position(const CastRay& a, const CastRay& b) {
  return std::lexicographical_compare(a.position_bits, a.position_bits + 3, b.position_bits,
                                      b.position_bits + 3);
}

// The point as the shading loop sees it, its shadow rays remembered: a ray to a position already
// answered at this point (`answered`, sorted) is not cast again; with `remember`, every ray cast
// is appended to `cast`. The answer is the same either way (ShadingPoint::visible depends on the
// light's position alone), so the image does not change.
class RememberedRays final : public ShadingPoint {
 public:
  RememberedRays(ShadingPoint& point, const std::vector<CastRay>& answered,
                 std::vector<CastRay>& cast, bool remember)
      : point_(point), answered_(answered), cast_(cast), remember_(remember) {}
  glm::vec3 position() const override { return point_.position(); }
  glm::vec3 normal() const override { return point_.normal(); }
  glm::vec3 unshadowed_radiance(const Light& world_light) const override {
    return point_.unshadowed_radiance(world_light);
  }
  SurfaceResponse surface_response() const override { return point_.surface_response(); }
  bool visible(const Light& world_light) override {
    CastRay ray{};
    std::memcpy(ray.position_bits, &world_light.position, sizeof ray.position_bits);
    const auto found = std::lower_bound(answered_.begin(), answered_.end(), ray, earlier_position);
    if (found != answered_.end() && !earlier_position(ray, *found)) {
      ++recalled_;
      return found->visible;
    }
    ray.visible = point_.visible(world_light);
    if (remember_) cast_.push_back(ray);
    return ray.visible;
  }
  // Rays answered from `answered`, which the shading loop counted as cast.
  std::uint64_t recalled() const { return recalled_; }

 private:
  ShadingPoint& point_;
  const std::vector<CastRay>& answered_;
  std::vector<CastRay>& cast_;
  bool remember_;
  std::uint64_t recalled_ = 0;
};

// The relative error, against the cut's unshadowed total, that holds each cluster's error within
// `relative_error` of what the rays showed (totals.visible, or kTotalFloorOfWhite of the display's
// white where less is shown: below that a pixel's error is not worth its rays, as for the drop
// budget). +inf where the cut holds nothing; at least the smallest normal float, which
// refine_light_cut can go on to.
float relative_error_against_shown(const CutTotals& totals, float relative_error,
                                   float display_scale) {
  const double shown = std::max(totals.visible, double(kTotalFloorOfWhite) / display_scale);
  const double error = double(relative_error) * shown / totals.unshadowed;
  if (!(error < double(relative_error))) return std::numeric_limits<float>::infinity();
  return std::max(float(error), std::numeric_limits<float>::min());
}

}  // namespace

glm::vec3 LevCutSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                          SelectionCounters& counters,
                                          glm::vec3* culled_irradiance_bound) const {
  LevCutScratch& own = method_scratch<LevCutScratch>(scratch);
  std::vector<std::uint8_t>& ray_visible = own.ray_visible;
  own.rays_cast.clear();
  own.rays_sorted.clear();
  const std::size_t shaded_from = scratch.inspect ? scratch.inspect->shaded.size() : 0;
  // The culled radiance bound is answered once, for the last cut (answer_light_cut_bounds).
  CulledRadianceBound culled_radiance;
  const bool bound_radiance = scratch.culled_radiance && culled_irradiance_bound;
  if (bound_radiance) {
    culled_radiance.surface = point.surface_response();
    scratch.walk.radiance = &culled_radiance;
  }
  float relative_error = relative_error_;
  // At relative error 0 (no clusters) or with the check off nothing is refined or remembered.
  const bool may_refine = relative_error_ > 0.0f && noise_sigmas_ > 0.0;
  glm::vec3 radiance(0.0f);
  for (int refinement = 0;; ++refinement) {
    const bool last = !may_refine || refinement == kNoiseRefinements;
    // A refined cut goes on from the last one (refine_light_cut) rather than from the root.
    WalkCounters walk_counters;
    if (refinement == 0) {
      scratch.lights.clear();
      start_light_cut(hierarchy_, volumes_, cut_nodes_, tolerance_, relative_error, point,
                      scratch.walk, scratch.lights, walk_counters, !last, bound_radiance,
                      1.0f / display_scale_);
    } else {
      refine_light_cut(hierarchy_, volumes_, cut_nodes_, tolerance_, relative_error, point,
                       scratch.walk, scratch.lights, walk_counters, !last);
    }
    counters.nodes_visited += walk_counters.nodes_visited;
    counters.lights_evaluated += walk_counters.lights_evaluated;
    // lights_tested is the size of the cut shaded: a refined one replaces the last. The rays, the
    // nodes and the lights evaluated are work done, every cut's.
    const std::uint64_t tested_before = counters.lights_tested;
    RememberedRays shading(point, own.rays_sorted, own.rays_cast, !last);
    radiance = shade_cut(shading, scratch, counters, ray_visible);
    counters.shadow_rays -= shading.recalled();
    if (last) break;
    const double noise = visibility_noise(scratch.walk.cut_estimates, ray_visible,
                                          scratch.walk.several_light_clusters);
    // NaN-safe: refines only on a noise known to be above the setting.
    const bool noisy = noise_sigmas_ * noise * display_scale_ > relative_error_;
    const float shown_error = relative_error_against_shown(
        cut_totals(scratch.walk.cut_estimates, ray_visible), relative_error_, display_scale_);
    const bool hidden = relative_error > kShownErrorAllowance * shown_error;
    if (!noisy && !hidden) break;
    if (scratch.cancel && scratch.cancel->load(std::memory_order_relaxed)) break;
    float finer = noisy ? relative_error * 0.5f : relative_error;
    if (hidden) finer = std::min(finer, shown_error);
    // The smallest relative errors halve or scale to 0, which refine_light_cut cannot go on to.
    if (!(finer > 0.0f)) break;
    // The inspector lists what the last cut did: the refined one. What the volumes dropped
    // stays dropped (and recorded); the clusters are decided again.
    if (scratch.inspect) {
      scratch.inspect->shaded.resize(shaded_from);
      scratch.inspect->walk_clusters.clear();
    }
    counters.lights_tested = tested_before;
    relative_error = finer;
    own.rays_sorted = own.rays_cast;
    std::sort(own.rays_sorted.begin(), own.rays_sorted.end(), earlier_position);
  }
  answer_light_cut_bounds(hierarchy_, tolerance_, scratch.walk, culled_irradiance_bound);
  scratch.walk.radiance = nullptr;
  if (culled_radiance.bounded) *scratch.culled_radiance = culled_radiance;
  return radiance;
}

glm::vec3 LevCutSelector::shade_cut(ShadingPoint& shading, SelectorScratch& scratch,
                                    SelectionCounters& counters,
                                    std::vector<std::uint8_t>& ray_visible) const {
  // The lights and the clusters' representatives alike: one shadow ray each.
  const std::size_t shaded_from = scratch.inspect ? scratch.inspect->shaded.size() : 0;
  // A centred cluster's ray goes to one of its lights (CutCluster); the rest to the light itself.
  const std::vector<CutCluster>& centred = scratch.walk.centred_clusters;
  std::size_t next_centred = 0;
  Light target;
  PlacedLightMemo& targets = scratch.walk.shadow_targets;
  targets.serve(cut_nodes_.first_lights.data(), cut_nodes_.draw_weights.data());
  const auto shadow_target = [&](std::size_t i, const Light&) -> const Light* {
    while (next_centred < centred.size() && centred[next_centred].index < i) ++next_centred;
    if (next_centred == centred.size() || centred[next_centred].index != i) return nullptr;
    const CutCluster& cluster = centred[next_centred];
    target = targets.find_or_make(
        cluster.node, cluster.linear.rotation, cluster.linear.scale, cluster.translation,
        [&] { return cluster_shadow_target(hierarchy_, cut_nodes_, cluster); });
    return &target;
  };
  // The walk computed each one's unshadowed radiance for its total when it cut (the same floats).
  const std::vector<glm::vec3>& estimates = scratch.walk.cut_estimates;
  assert(estimates.empty() || estimates.size() == scratch.lights.size());
  const glm::vec3* unshadowed =
      estimates.size() == scratch.lights.size() ? estimates.data() : nullptr;
  ray_visible.assign(scratch.lights.size(), 0);
  const glm::vec3 radiance = sum_visible_lights(
      scratch.lights, [](const Light&) { return true; }, shading, counters, scratch.cancel, nullptr,
      scratch.inspect, shadow_target, unshadowed, ray_visible.data());
  if (scratch.inspect) scratch.inspect->attach_walk_clusters(shaded_from);
  return radiance;
}

std::size_t LevCutSelector::bookkeeping_bytes() const {
  return cut_nodes_.draw_weights.size() * sizeof(double) + cut_nodes_.centred.size() +
         (cut_nodes_.drawn_lights.size() + cut_nodes_.first_lights.size() +
          cut_nodes_.light_counts.size()) *
             sizeof(std::uint32_t);
}

}  // namespace lev
