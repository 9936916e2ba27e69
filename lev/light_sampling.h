// The importance descent that the sampling methods share (lev_mc's culled rest, light_tree's
// whole hierarchy): from a subtree, choose a child with probability proportional to its
// importance at the point, down to one light, and return that light in world space with the
// probability of having chosen it. An estimator that weighs the light's contribution by
// 1/probability is unbiased as long as every light that can light the point has a non-zero
// probability; the importance is therefore zero only where the aggregate bound of light_bounds.h
// is (no light of the subtree can shine on the point) or where every light lies behind the
// surface.
//
// The importance of a subtree is its light aggregate's bound at the point, with two refinements
// from pbrt-v4's LightBounds::Importance that make it an estimate rather than a worst case: the
// distance is measured to the centre of the box of light positions, clamped below at half its
// diagonal (so a point inside the box gets a finite importance instead of irradiance_bound's
// infinity), and with a surface normal the bound of cos(theta) between the normal and the
// directions to the box multiplies it (the smaller of the sphere's bound and the projection's of
// light_bounds.h, which sees a layer of lights in a ceiling arrive at grazing angles). A single
// light's importance is its exact irradiance times that cosine, with a small share of its bound
// where the exact value is zero, so rounding at the edge of a spot cone or of the surface plane
// never makes a contributing light unreachable.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lev/important_lights.h"
#include "lev/light.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// The point lights are sampled for: its world position and, when the surface is known, its unit
// normal on the side lights must be on (zero when any side may be lit).
struct SamplingPoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
};

struct SampledLight {
  Light light;               // world space
  double probability = 0.0;  // of choosing this light, > 0
};

// A whole hierarchy as the descent's starting subtree (the root in the world frame).
SubtreeRef whole_hierarchy(const LightHierarchy& hierarchy, const glm::vec3& world_point);

// The importance of the subtree at `node` entered in `world_from_local`, with `local` the point
// in that frame and `local_normal` the normal turned into it.
double subtree_importance(const LightHierarchy& hierarchy, std::uint32_t node,
                          const FramePoint& local, const glm::vec3& local_normal);
// The importance of one light, light and point in the same frame.
double light_importance(const Light& light, const FramePoint& x, const glm::vec3& normal);

// Index of the item whose cumulative weight first exceeds u * total (u in [0, 1)); only items of
// non-zero weight are chosen. total = the sum of weights, > 0.
std::size_t choose_weighted(const std::vector<double>& weights, double total, float u);

// One descent from `start`, one uniform number per choice from `random`. `weights` is scratch.
// The light and its probability within the subtree (the caller multiplies in how it chose the
// subtree); a union whose children all have zero importance (none can light the point) is
// descended uniformly, so the probabilities over the subtree's lights sum to 1. nodes_visited
// counts the importances computed.
void sample_light(const LightHierarchy& hierarchy, const SubtreeRef& start,
                  const SamplingPoint& point, RandomStream& random, std::vector<double>& weights,
                  SampledLight& sampled, std::uint64_t& nodes_visited);

// Every light of the subtree with the probability sample_light gives it (zero included), in the
// hierarchy's depth-first order: the descent enumerated, for tests and for checks of the
// estimators.
void light_probabilities(const LightHierarchy& hierarchy, const SubtreeRef& start,
                         const SamplingPoint& point, std::vector<SampledLight>& lights);

// How many parts open_wide_parts may leave for k draws. The opening costs an importance per part
// once per point and pays back in every draw: on the hall (4,096 lights), 64 parts cost about
// three draws and cut the variance of a draw to 0.4x, a gain from about 4 draws on, a loss below
// (16 parts cost half a draw for 0.9x). So fewer than kDrawsToOpen draws open only up to
// kFewDrawsParts parts (the root's children, whose importances a descent computes anyway), and
// from there on the budget grows with k.
inline constexpr int kDrawsToOpen = 4;
inline constexpr std::size_t kFewDrawsParts = 4;
inline constexpr std::size_t kPartsPerDraw = 16;
inline constexpr std::size_t kMaxSampledParts = 256;
inline std::size_t sampled_parts_budget(int k) {
  if (k < kDrawsToOpen) return kFewDrawsParts;
  return std::min(kMaxSampledParts, kPartsPerDraw * static_cast<std::size_t>(k));
}

// Spots of one subtree whose aims lie more than this apart (radians) make its importance weak.
inline constexpr float kWideAxisSpread = 0.1f;

// Opens, breadth first, every subtree part whose spots aim more than kWideAxisSpread apart into
// its children, as long as the parts (subtrees and lights) stay within max_parts. The importance
// of such a subtree bounds its spot cone by the widest of its aims, and so weighs alike the lights
// that shine at the point and those that shine away (the hall's rig: a quadrant of fixtures aimed
// at the stage from every side); its children, each aimed one way, are weighed apart. The parts
// keep the same lights, each once, so an estimator over them stays unbiased. `queue` is scratch.
void open_wide_parts(const LightHierarchy& hierarchy, CulledParts& parts, std::size_t max_parts,
                     std::vector<SubtreeRef>& queue);

// The per-thread buffers of a sampling method (its MethodScratch).
struct SamplingScratch final : MethodScratch {
  CulledParts parts;
  std::vector<SubtreeRef> queue;
  std::vector<double> part_weights;
  std::vector<double> weights;
  // Set by sampled_radiance: every part's importance was zero at the point (their lights behind
  // the surface, dark there or of no intensity), so they add nothing and no draw was made.
  bool nothing_to_draw = false;
};

// The estimator both sampling methods use on scratch.parts: first opened (open_wide_parts, within
// sampled_parts_budget(k)), then k draws, each choosing one of the parts (a subtree or a single
// world light) with probability proportional to its importance and then, for a subtree, a light
// by sample_light; one shadow ray per draw, its radiance weighed by 1/probability, the mean of
// the k returned. Its expected value is the summed unshadowed-and-visible radiance of every
// light in the parts. draw_square_sum (may be null) gains the sum over the k draws of each
// draw's weighed radiance squared, for the estimate's variance (the missed light). record (may be
// null: the pixel inspector's) gains each draw as a sampled light with its weight.
glm::vec3 sampled_radiance(const LightHierarchy& hierarchy, int k, ShadingPoint& point,
                           RandomStream& random, SamplingScratch& scratch,
                           SelectionCounters& counters, glm::dvec3* draw_square_sum = nullptr,
                           InspectRecord* record = nullptr);

}  // namespace lev
