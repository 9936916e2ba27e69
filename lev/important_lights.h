// The query of thesis fig. 3.5: walk the hierarchy from the root with a world-space point, skip
// every subtree whose extent volume does not contain the point, and return the lights whose
// irradiance at the point reaches the tolerance, in world space, in the hierarchy's depth-first
// order. Next to it, the references the tests compare it with: a brute force over every light,
// and a flattening of the description that shares no code with the walk.
#pragma once

#include <cstdint>
#include <vector>

#include "lev/hierarchy_cursor.h"
#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_description.h"
#include "lev/light_hierarchy.h"
#include "lev/placed_light_memo.h"

namespace lev {

class ShadingPoint;    // light_selector.h
struct InspectRecord;  // inspect_record.h

struct WalkCounters {
  // Extent volumes tested: every box test (a union's children, extent-volume and master nodes)
  // and every light's exact irradiance test.
  std::uint64_t nodes_visited = 0;
  // The lights of lev_cut's exact clusters whose unshadowed radiance it summed.
  std::uint64_t lights_evaluated = 0;
};

// The rotation and scale of a world_from_local transform. The walk keeps them apart from the
// translation: translations (most affine nodes of instanced scenes) only move the translation,
// which travels in the frame, and a new entry is made only below a rotating or scaling node.
struct WalkLinear {
  glm::mat3 rotation{1.0f};
  float scale = 1.0f;
};

// A subtree still to walk: its node, the query point in its frame, and the frame's
// world_from_local transform (rotation and scale by index, translation by value).
struct WalkFrame {
  glm::vec3 local_point{0.0f};
  std::uint32_t node = 0;
  glm::vec3 world_translation{0.0f};
  std::uint32_t linear = 0;    // index into WalkScratch::linear; 0 is the identity
  bool volume_tested = false;  // the subtree's box was tested by its parent (skip one test)
};

// A part of a culled subtree whose bound is being tightened (tightened_irradiance_bound): its
// node and the query point in the frame the node is entered with.
struct BoundPart {
  std::uint32_t node = 0;
  FramePoint point;
};

// A part of a culled subtree in the best-first tightening of the culled radiance bound
// (CulledRadianceBound): its node, the query point and the surface's directions in the frame the
// node is entered with, and its radiance bound there (RGB, and the brightest channel as the key).
struct RadiancePart {
  float key = 0.0f;
  std::uint32_t sequence = 0;  // order of making: ties go to the earlier, as for DeferredSubtree
  std::uint32_t node = 0;
  FramePoint point;
  glm::vec3 normal{0.0f};
  glm::vec3 mirrored_view{0.0f};
  glm::vec3 bound{0.0f};
  glm::vec3 irradiance{0.0f};  // its irradiance bound, summed into the walk's when it is settled
};

// A request for the culled radiance bound, set in WalkScratch::radiance by the caller for one
// walk (LevSelector, when the renderer wants the error bound): find_important_lights_tight_bound
// then also bounds the summed unshadowed radiance (ShadingPoint::unshadowed_radiance: irradiance
// times the Phong response toward the light, zero from behind) of every light it did not return,
// at a surface of this response. The irradiance bound times the material's largest response
// ignores where the lights lie around the surface; this bound takes each culled part's box into
// account (radiance_bound), so lights behind the surface, at grazing angles or outside a narrow
// specular lobe count for what they can add. Culled subtrees are opened best first, the part with
// the largest bound next, within kRadianceOpeningsPerPoint unions; the walk's irradiance bound is
// then the sum of the same parts' irradiance bounds (certified as well, and cheaper than
// tightening it apart), so it may differ from the one computed without the request.
struct CulledRadianceBound {
  SurfaceResponse surface;  // in: world frame
  bool bounded = false;     // out: the walk answered
  glm::vec3 bound{0.0f};    // out: RGB
};

// How many unions one shading point may open to tighten its culled bound: the work stays a small
// multiple of the walk's, and a part left unopened keeps its (certified) aggregate bound.
inline constexpr int kBoundOpeningsPerPoint = 64;

// How many unions one shading point may open to tighten its culled radiance bound. Measured on
// building 256 at tolerance 0.01, 160x120, callgrind instructions of the whole render (before
// the radiance bound: 1.42e9, bound avg / max 18.5 / 100 %): 0 openings 1.20e9, 7.2 / 96.8 %;
// 4: 1.36e9, 4.3 / 31 %; 8: 1.53e9, 3.7 / 24 %; 16: 1.84e9, 3.3 / 22 %; 64: 3.82e9, 2.9 / 18 %.
inline constexpr int kRadianceOpeningsPerPoint = 8;

// What the relative cut (find_light_cut) reads of a node for every cluster it makes, worked out
// once per hierarchy (make_cut_node_table) instead of once per cluster and point: the weight a
// draw of one light gives the subtree entered at the node (its lights' summed intensity, as
// light_cut_tree.h's draw_weight, times its transforms' scale squared) and whether a centred
// representative stands for it (important_lights.cpp, centred_cluster). Both parallel to
// LightHierarchy::nodes. The draws read the same doubles they computed per call before, so the
// cut and its rays are unchanged; on stage 4,608 the per-call work was a fifth of lev_cut's time.
struct CutNodeTable {
  std::vector<double> draw_weights;
  std::vector<std::uint8_t> centred;
  // The light an unshifted draw from the node ends at, when no transform lies on the way down
  // (the drawn representative's light then depends on the node alone); ~0u otherwise.
  std::vector<std::uint32_t> drawn_lights;
  // The first light below the node (a centred representative's parameters), when only
  // translations lie on the way down; ~0u otherwise.
  std::vector<std::uint32_t> first_lights;
  // The lights below the node, instances expanded (saturating at the largest uint32): a cluster
  // of at most kExactClusterLights is shaded from its own lights.
  std::vector<std::uint32_t> light_counts;
};
CutNodeTable make_cut_node_table(const LightHierarchy& hierarchy);

// A cluster of the relative cut (find_light_cut) that a centred representative stands for (the
// centre of its lights' box, lev_est's): the representative at `index` of the lights the walk
// appended, and the subtree, entered with world_from_local = (linear, translation). Its shadow
// ray goes to cluster_shadow_target.
struct CutCluster {
  std::size_t index = 0;
  std::uint32_t node = 0;
  WalkLinear linear;
  glm::vec3 translation{0.0f};
};

// A subtree of the relative cut (find_light_cut) decided as a whole, put aside or kept as a
// cluster, entered with world_from_local = (linear, world_translation) and the walk's point
// local_point in that frame. Its frame is kept whole, the rotation by value: it leaves the
// stack's order.
struct CutSubtree {
  std::uint32_t node = 0;
  bool volume_tested = false;
  bool identity = true;  // the frame's rotation and scale are the identity
  bool centred = false;  // its representative is centred (CutCluster)
  glm::vec3 local_point{0.0f};
  glm::vec3 world_translation{0.0f};
  WalkLinear linear;
  // Its unshadowed radiance, as the running total counts it: its representative's, or an exact
  // cluster's sum over its lights.
  glm::vec3 estimate{0.0f};
  glm::vec3 irradiance_bound{0.0f};  // of the subtree: what its cluster leaves uncertain
  glm::vec3 radiance_bound{0.0f};    // of the subtree at the point's surface (RGB)
  // When it is a cluster of the cut before (refine_light_cut): its light's index among those
  // that cut appended (WalkScratch::previous_lights), and whether its ray stood for two lights or
  // more (WalkScratch::several_light_clusters); kNotKept otherwise.
  std::uint32_t kept_as = kNotKept;
  bool several = false;
  static constexpr std::uint32_t kNotKept = ~0u;
};

// A subtree the relative cut put aside because its cluster bound was too large for the point's
// running total: walked later, largest bound first, or kept as a cluster when the total allows.
struct DeferredSubtree : CutSubtree {
  Light representative;  // in world space, carrying the subtree's intensity
};

// What a relative cut summed at a point (find_light_cut's walk), kept so that a finer cut can go
// on from it (refine_light_cut) and the bounds be answered once, for the last cut
// (answer_light_cut_bounds).
struct LightCutSums {
  glm::dvec3 total{0.0};            // the running total: the estimate of the cut
  glm::dvec3 culled{0.0};           // the irradiance bounds of what the volumes dropped
  glm::dvec3 clusters{0.0};         // the clusters' irradiance bounds
  glm::dvec3 cluster_error{0.0};    // the clusters' radiance error (CulledSoFar::cluster_error)
  glm::dvec3 radiance_culled{0.0};  // the culled lights' radiance bounds
  std::uint32_t radiance_parts_made = 0;
  std::uint32_t deferrals = 0;
  bool radiance = false;  // the culled radiance bound's parts are collected (scratch.radiance)
  // The radiance bounds of what the volumes dropped, at the point's surface, and the budget
  // they were dropped within (start_light_cut).
  glm::dvec3 dropped{0.0};
  float drop_budget = 0.0f;
  float total_floor = 0.0f;  // the least total a cluster is judged against (kTotalFloorOfWhite)
};

// The heap's entry for a DeferredSubtree: the order is read from these 12 bytes alone, so the
// heap moves them rather than the 200-byte subtrees.
struct DeferredKey {
  float bound = 0.0f;          // brightest channel of its radiance bound
  std::uint32_t sequence = 0;  // order of deferral: ties go to the earlier, so nothing is left to
                               // how the standard library breaks them
  std::uint32_t subtree = 0;   // its index in WalkScratch::deferred
};

// Reused between queries so that a walk allocates nothing once warm.
struct WalkScratch {
  std::vector<WalkFrame> stack;
  std::vector<WalkLinear> linear;
  std::vector<BoundPart> bound_parts;
  std::vector<DeferredSubtree> deferred;     // find_light_cut's subtrees put aside this query
  std::vector<DeferredKey> deferred_heap;    // their keys, a heap, largest bound on top
  std::vector<RadiancePart> radiance_parts;  // a heap, largest bound on top
  // When set, find_important_lights_tight_bound answers it (CulledRadianceBound); null otherwise.
  CulledRadianceBound* radiance = nullptr;
  // When set (the pixel inspector, SelectorScratch::inspect), the walk also records there what it
  // culls and the clusters it makes; null in renders.
  InspectRecord* inspect = nullptr;
  // find_light_cut's clusters with a centred representative, in the order of their lights.
  std::vector<CutCluster> centred_clusters;
  // find_light_cut's representatives of the subtrees it decides, and lev_cut's shadow-ray targets
  // of its centred clusters (cluster_shadow_target), by node and frame.
  PlacedLightMemo representatives;
  PlacedLightMemo shadow_targets;
  // find_light_cut's unshadowed radiance of each light and representative it appends, in their
  // order, as its running total counted them (when it cuts: relative error above 0; else empty),
  // so that shading them need not compute it again.
  std::vector<glm::vec3> cut_estimates;
  // find_light_cut's clusters shaded from their own lights (exact clusters): the index of each
  // one's light among those it appended, in order. Its estimate (cut_estimates) is the summed
  // unshadowed radiance of the cluster's lights; the light is the one its shadow ray goes to.
  std::vector<std::size_t> exact_clusters;
  // find_light_cut's clusters whose one shadow ray stands for two lights or more (centred, drawn,
  // and exact ones with two lit lights or more), the index of each one's light among those it
  // appended, in order: where their rays are noisy (lev/visibility_noise.h).
  std::vector<std::size_t> several_light_clusters;
  // An exact cluster's light drawn for its shadow ray, and the parts of its subtree still to
  // step through.
  Light cluster_light;
  std::vector<SubtreePart> subtree_parts;
  // The last relative cut's sums, and (when it may be refined) the clusters it kept, in the
  // order of their lights; refine_light_cut moves that cut's lights to previous_lights.
  LightCutSums cut_sums;
  std::vector<CutSubtree> kept_clusters;
  std::vector<CutSubtree> previous_kept;
  std::vector<Light> previous_lights;
  std::vector<glm::vec3> previous_estimates;
};

// A subtree the walk culled: its node, entered in the frame world_from_local, and the query point
// in that frame (with its rounding allowance, as irradiance_bound takes it).
struct SubtreeRef {
  std::uint32_t node = 0;
  Similarity world_from_local;
  FramePoint point;
};

// Everything the walk culled at one point, so that a method can still account for it (lev_mc
// samples it): the subtrees whose volume missed the point, and the lights below the tolerance
// whose irradiance there is not zero, in world space (the walk's own copies, so the same floats
// rt shades). Lights that cannot light the point are left out. The walk's lights and these
// parts together hold every light of the scene that can light the point, each once.
struct CulledParts {
  std::vector<SubtreeRef> subtrees;
  std::vector<Light> lights;
  void clear() {
    subtrees.clear();
    lights.clear();
  }
};

// Appends to important_lights every light with irradiance >= tolerance at point. `volumes` are
// the hierarchy's, fitted for `tolerance` (or a smaller one, which culls less).
// When culled_irradiance_bound is given, it receives an upper bound of the summed irradiance (RGB,
// light.h's irradiance()) at point of every light not returned: the exact irradiance of each
// light tested and culled plus the aggregate bound (light_bounds.h) of each subtree whose volume
// missed the point, summed where the walk culls them. Without it the walk skips that work.
void find_important_lights(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                           float tolerance, const glm::vec3& point, WalkScratch& scratch,
                           std::vector<Light>& important_lights, WalkCounters& counters,
                           glm::vec3* culled_irradiance_bound = nullptr);

// find_important_lights with a tighter culled_irradiance_bound (the same lights and counters):
// a culled subtree whose aggregate bound exceeds the tolerance, as it does wherever the point lies
// in or near the box of its light positions (irradiance_bound is +inf inside it), is bounded by
// its parts instead (tightened_irradiance_bound), so the bound stays finite where LEV culls
// lights that sit around the point. `lev` reports this bound; lev_est's gate keeps the cheaper one.
// With scratch.radiance set and culled_irradiance_bound given, it also answers the culled radiance
// bound (CulledRadianceBound).
void find_important_lights_tight_bound(const LightHierarchy& hierarchy,
                                       const ExtentVolumes& volumes, float tolerance,
                                       const glm::vec3& point, WalkScratch& scratch,
                                       std::vector<Light>& important_lights, WalkCounters& counters,
                                       glm::vec3* culled_irradiance_bound = nullptr);

// The culled radiance bound (CulledRadianceBound) of LEV's walk alone at `tolerance`, for a
// method whose own walk culls what this one culls or less (lev_est's clusters stand for part of
// it, lev_cut's volumes drop a subset of it): the tight walk made again for `surface`, its lights
// kept in `lights` (cleared; scratch) and dropped, its counters too, and no inspector record.
CulledRadianceBound lev_culled_radiance_bound(const LightHierarchy& hierarchy,
                                              const ExtentVolumes& volumes, float tolerance,
                                              const glm::vec3& point,
                                              const SurfaceResponse& surface, WalkScratch& scratch,
                                              std::vector<Light>& lights);

// An upper bound of the summed irradiance (RGB) of the lights of the subtree at `node` at x
// (in the frame the node is entered with): the subtree's aggregate bound where that is at most
// `refine_above` (brightest channel), else the sum of its children's bounds, opened the same way
// depth first while *openings_left > 0 (each union opened takes one); a light is bounded by its
// own aggregate. Never below irradiance_bound's sum over the same lights' exact irradiance, so it
// stays certified; never above the subtree's aggregate bound. `parts` is scratch.
glm::dvec3 tightened_irradiance_bound(const LightHierarchy& hierarchy, std::uint32_t node,
                                      const FramePoint& x, float refine_above, int& openings_left,
                                      std::vector<BoundPart>& parts);

// Reference for the tests: the summed unshadowed radiance at `point` (its unshadowed_radiance) of
// the lights of a flattened list that fail is_important, which CulledRadianceBound bounds.
glm::dvec3 culled_radiance_brute_force(const std::vector<Light>& world_lights,
                                       const ShadingPoint& point, float tolerance);

// find_important_lights, keeping in `culled` (cleared first) what it culls instead of dropping it.
void find_important_and_culled(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                               float tolerance, const glm::vec3& point, WalkScratch& scratch,
                               std::vector<Light>& important_lights, WalkCounters& counters,
                               CulledParts& culled);

// The walk of `lev_bounded`: like find_important_lights, but a subtree or light is culled only
// while the running sum of what was culled at this point (the culled_irradiance_bound above) stays
// within the tolerance, compared on the scale of the per-light test (its brightest channel); a
// subtree that does not fit is walked as if its volume held the point, a light that does not fit
// is returned. So max(culled_irradiance_bound) <= tolerance (computed whether asked for or not).
// What is culled depends on the depth-first order only: deterministic.
void find_lights_within_budget(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                               float tolerance, const glm::vec3& point, WalkScratch& scratch,
                               std::vector<Light>& lights, WalkCounters& counters,
                               glm::vec3* culled_irradiance_bound = nullptr);

// Where find_lights_and_clusters cuts what it culls, on the scale of the per-light test (the
// brightest channel of an irradiance bound).
struct ClusterCut {
  // A culled subtree whose bound exceeds this is not culled whole: it is walked, and its parts
  // (smaller subtrees, single lights) are culled instead.
  float refine_above = 0.0f;
  // A culled part whose bound exceeds this becomes a cluster; the rest is only summed.
  float keep_above = 0.0f;
  // lev_est estimates the culled rest only where its bound exceeds this share of the irradiance
  // of the tested lights found visible (the walk does not read it).
  float rest_share_of_seen = 0.0f;
};

// The walk of `lev_est`: like find_important_lights (the same lights), and everything it culls
// cut into parts whose irradiance bound is at most cut.refine_above; each part brighter than
// cut.keep_above is appended to `clusters` (in depth-first order) as one light in world space: a
// culled light itself, or a culled subtree's representative (Lightcuts', Walter et al. 2005): a
// light like the subtree's first one, at the centre of the box around the subtree's light
// positions, aimed along the axis of its spots' direction cone (when that cone is narrower than
// a hemisphere), carrying the summed intensity of the subtree. culled_irradiance_bound, as
// find_important_lights', counts every culled part, clusters included.
void find_lights_and_clusters(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                              float tolerance, const ClusterCut& cut, const glm::vec3& point,
                              WalkScratch& scratch, std::vector<Light>& important_lights,
                              std::vector<Light>& clusters, WalkCounters& counters,
                              glm::vec3* culled_irradiance_bound = nullptr);

// The walk of `lev_cut`: LEV's extent volumes drop what lies below the tolerance (as
// find_important_lights does), and what remains is cut relative to the point, as Lightcuts cuts
// (Walter et al. 2005): a subtree whose cluster bound (radiance_bound: irradiance bound times the
// material's response bound over its box, visibility 1, brightest channel) is at most
// relative_error times the running total (at least kTotalFloorOfWhite of display_white, below:
// an error that small is not worth rays) becomes one cluster, its representative (as
// find_lights_and_clusters makes it) appended to `lights`; a larger one is put aside, and once
// the walk has nothing else left the largest bound put aside is walked, until every bound left
// is within the criterion. The running total is the estimate of the cut so far, as in Lightcuts:
// the unshadowed radiance (ShadingPoint::unshadowed_radiance) of every light appended and of the
// representative of every cluster, appended or put aside. A cluster of at most 32 lights that a
// drawn representative would stand for is an exact cluster (WalkScratch::exact_clusters): its
// estimate is its lights' summed unshadowed radiance, and the light appended is one of them,
// drawn in proportion to that radiance by a hash of the point, for its shadow ray. Lights above
// the tolerance are appended themselves. At relative error 0 nothing is clustered or
// put aside: the walk is find_important_lights', its lights in the same order.
// culled_irradiance_bound, as find_important_lights', counts what the volumes dropped and the
// clusters' irradiance bounds (an estimate is not exact). With scratch.radiance set and
// culled_irradiance_bound given, it also answers the radiance error bound (CulledRadianceBound):
// what the volumes dropped, bounded at the surface as find_important_lights_tight_bound bounds
// it, plus per cluster the larger of its representative's unshadowed radiance and its radiance
// bound, as neither the estimate nor the light it stands for can leave [0, that].
//
// What the volumes drop is each light below the tolerance, but many such lights may light the
// point together: their radiance bound (at the point's surface) is held within the relative
// error of the cut's total, as one more cluster's would be, or, where the total is about 0 and
// every bound loose, of kTotalFloorOfWhite of the display's white (display_white: the radiance
// shown as white, 1 / the exposure), the least total a cluster is judged against too. A point whose
// drop exceeds that is walked again with it as the drop's budget: past it, a subtree the volumes
// would drop is cut instead and a light they would drop is kept.
void find_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                    const CutNodeTable& table, float tolerance, float relative_error,
                    ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                    WalkCounters& counters, glm::vec3* culled_irradiance_bound = nullptr,
                    float display_white = 1.0f);

// The least total, as a share of the display's white, that a relative cut judges its errors
// against: a cluster's bound may reach the relative error of the larger of the cut's total and
// this (find_light_cut's criterion), and what its volumes drop may add up to as much. An error
// below it is not worth its rays where the total is dark: the metrics and the tolerance are in
// exposed linear units (renderer/display_transform.h), where 8 bits step by 1/255 of white.
// Without it, a point no light reaches (bounds are loose and the total about 0) was walked to
// its lights: the car park's ceiling walked 9,508 nodes per point for 87 at exposure 0, and at
// exposure 8, where the volumes drop little, 9,566 nodes for 144. Against the cut's total
// alone, at relative error 0.02 (`levrt render --scene S --method lev_cut --rt-fallback off
// --subsample 4`): hall 4,096 200 rays per point for 171 with it, hall 16,384 (0.025) 174 for
// 150, the stage 388 for 310, every maximum error the same; a quarter of white saved 15-20 %
// more rays and raised the averages by half (docs/results/lev_cut.md).
inline constexpr float kTotalFloorOfWhite = 0.1f;

// find_light_cut in steps, for a method that may cut a point again finer (lev_cut's noise
// check): start_light_cut makes the cut and leaves its bounds unanswered; with may_refine it
// keeps its clusters (WalkScratch::kept_clusters) for refine_light_cut. bound_radiance collects
// the culled radiance bound's parts (scratch.radiance must be set).
void start_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                     const CutNodeTable& table, float tolerance, float relative_error,
                     ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                     WalkCounters& counters, bool may_refine, bool bound_radiance,
                     float display_white);
// Goes on from the last cut at this point (start_light_cut or refine_light_cut with may_refine,
// its lights in `lights`) to a cut at a smaller relative_error, without walking from the root
// again: its lights stay, each cluster is put aside again with its bound and walked if that now
// exceeds relative_error times the cut's total, and the walk goes on as find_light_cut's does.
// What the volumes dropped stays dropped, and what they drop now is held within the first cut's
// drop budget (find_light_cut); an exact cluster kept again keeps its light and sum.
// `lights` and the walk's lists (cut_estimates, centred, exact and several-light clusters) are
// those of the finer cut: its own lights first, then its clusters in the order decided.
void refine_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                      const CutNodeTable& table, float tolerance, float relative_error,
                      ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                      WalkCounters& counters, bool may_refine);
// The last cut's bounds, as find_light_cut answers them: culled_irradiance_bound when given, and
// scratch.radiance when the cut collected its parts.
void answer_light_cut_bounds(const LightHierarchy& hierarchy, float tolerance, WalkScratch& scratch,
                             glm::vec3* culled_irradiance_bound);

// Where a centred cluster's shadow ray goes (CutCluster): one of its lights in world space,
// drawn in proportion to intensity, fixed per cluster and different between the instances of one
// master (important_lights.cpp, cluster_draw_shift).
Light cluster_shadow_target(const LightHierarchy& hierarchy, const CutNodeTable& table,
                            const CutCluster& cluster);

// Every light of the scene in world space, instances expanded, in the same depth-first order as
// the walk and through the same arithmetic, so a light here is bit-identical to the one the walk
// returns.
std::vector<Light> flatten_lights(const LightHierarchy& hierarchy);

// Reference: every light of the description in world space, by plain recursion over the
// LightDescription (instances expanded, transforms composed from the root down, each light moved by
// transform_light). Independent of build_hierarchy and of the walk, it yields the same lights in
// the same order, and with the same floats (the walk's arithmetic is this composition's, split).
std::vector<Light> flatten_light_description(const LightDescription& tree);

// Reference: the lights of a flattened list that pass is_important (for tests).
std::vector<Light> important_lights_brute_force(const std::vector<Light>& world_lights,
                                                const glm::vec3& point, float tolerance);

}  // namespace lev
