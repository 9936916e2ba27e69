// The walk over the light hierarchy (important_lights.h). Over 600 lines on purpose: the walk is
// one template instantiated for every method, and the helpers it calls per node and per light
// (passes, visit_light, cull_subtree, cut_or_defer, the culled-bound bookkeeping) sit beside it so
// that each instantiation inlines them; the brute-force references the tests compare it with stay
// next to it, as lev/ keeps them.
#include "lev/important_lights.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "lev/bounds.h"
#include "lev/hierarchy_cursor.h"
#include "lev/inspect_record.h"
#include "lev/light_bounds.h"
#include "lev/light_cut_tree.h"
#include "lev/light_selector.h"

namespace lev {
namespace {

// Frames are written field by field straight into the stack, and the world transform of the
// subtree being walked stays in locals: a struct assembled in memory with narrow stores and read
// back whole stalls on store forwarding, which was the walk's largest cost.
void push_frame(std::vector<WalkFrame>& stack, const glm::vec3& local_point, std::uint32_t node,
                const glm::vec3& world_translation, std::uint32_t linear, bool volume_tested) {
  WalkFrame& frame = stack.emplace_back();
  frame.local_point = local_point;
  frame.node = node;
  frame.world_translation = world_translation;
  frame.linear = linear;
  frame.volume_tested = volume_tested;
}

// Appends the light seen through world_from_local = (linear, translation). With the identity
// linear part this is transform_light's arithmetic without the products by one (which are
// exact), so the floats are the same either way. Written in place, like the frames.
Light& push_world_light(std::vector<Light>& out, const Light& light, const WalkLinear& linear,
                        bool identity, const glm::vec3& translation) {
  Light& l = out.emplace_back(light);
  if (identity) {
    l.position = light.position + translation;
    if (light.kind == LightKind::spot) l.direction = glm::normalize(light.direction);
  } else {  // transform_light(light, {linear.rotation, linear.scale, translation}), in place
    l.position = linear.rotation * (linear.scale * light.position) + translation;
    l.intensity = light.intensity * (linear.scale * linear.scale);
    l.range = light.range * linear.scale;
    if (light.kind == LightKind::spot)
      l.direction = glm::normalize(linear.rotation * light.direction);
  }
  return l;
}

constexpr std::uint32_t kNoNode = ~0u;

// The deferred subtrees' heap order: the largest bound on top, the earlier deferral first.
bool smaller_deferred_bound(const DeferredKey& a, const DeferredKey& b) {
  return a.bound < b.bound || (a.bound == b.bound && a.sequence > b.sequence);
}

// The walk reads nodes through one of these: the structure alone (flattening, which culls
// nothing) or the nodes fitted with their volumes (the query).
struct StructureNodes {
  const HierarchyNode* nodes;
  const HierarchyNode& node(std::uint32_t i) const { return nodes[i]; }
};
struct FittedNodes {
  const FittedNode* nodes;
  const HierarchyNode& node(std::uint32_t i) const { return nodes[i].node; }
  const Bounds& volume(std::uint32_t i) const { return nodes[i].volume; }
};

// What the walk does with what it culls: drop it, also sum its irradiance bound, cull only
// while that sum stays within the tolerance (find_lights_within_budget), also cut it into
// clusters for an estimate (find_lights_and_clusters), or keep it (CulledParts, for sampling).
// `tight` is summed with each culled subtree's bound tightened (tightened_irradiance_bound).
// `relative` sums it too, and cuts what the volumes keep relative to the point (find_light_cut).
enum class Culled { dropped, summed, tight, budgeted, clustered, collected, relative };

// What has been culled so far at this point: the summed bound and, when clustered, the cut;
// when collected, the culled parts themselves.
struct CulledSoFar {
  // In double: a million culled terms summed in float would drift by up to 1%.
  glm::dvec3 sum{0.0};
  ClusterCut cut;
  std::vector<Light>* clusters = nullptr;  // representatives
  CulledParts* parts = nullptr;
  // When tight: the unions the point may still open, and their scratch.
  int openings_left = 0;
  std::vector<BoundPart>* bound_parts = nullptr;
  // When tight and asked for the culled radiance bound (WalkScratch::radiance): the culled
  // lights' radiance bounds summed, and the culled subtrees kept as parts to open best first.
  CulledRadianceBound* radiance = nullptr;
  glm::dvec3 radiance_sum{0.0};
  std::vector<RadiancePart>* radiance_parts = nullptr;
  std::uint32_t radiance_parts_made = 0;
  // When relative and cutting (relative_error > 0): the point and its surface, and the running
  // total of the unshadowed radiance of the lights and representatives kept so far.
  ShadingPoint* shading = nullptr;
  SurfaceResponse surface;
  float relative_error = 0.0f;
  glm::dvec3 total{0.0};
  std::uint32_t deferrals = 0;
  // The unshadowed radiance of each light and representative appended to the walk's output, in
  // its order (WalkScratch::cut_estimates): what the total counted, for the shading to reuse.
  std::vector<glm::vec3>* estimates = nullptr;
  // The radiance error the clusters of the cut may make: per cluster, its estimate E stands for
  // a shadowed radiance C in [0, its radiance bound B], so |E - C| <= max(E, B) (per channel).
  glm::dvec3 cluster_error{0.0};
  // When relative: the clusters' irradiance bounds (apart from `sum`, what the volumes dropped,
  // which a finer cut keeps), and, when set, the record of each cluster kept, for a finer cut
  // (WalkScratch::kept_clusters).
  glm::dvec3 cluster_sum{0.0};
  std::vector<CutSubtree>* kept = nullptr;
  // When relative and set: the walk goes on from a cut before (refine_light_cut): it starts
  // from the subtrees put aside, not from the root.
  bool go_on = false;
  // When relative and cutting: the radiance bounds (at the point's surface) of what the volumes
  // dropped, and the most their brightest channel may reach: past it, a subtree the volumes
  // would drop is cut instead, and a light they would drop is kept (start_light_cut).
  glm::dvec3 dropped{0.0};
  float drop_budget = std::numeric_limits<float>::infinity();
  // When relative and cutting: the least total a cluster's bound is judged against
  // (kTotalFloorOfWhite of the display's white; start_light_cut).
  float total_floor = 0.0f;
  // When relative: the clusters of the cut stood for by a centred representative (CutCluster),
  // and what the cut reads of each node (CutNodeTable).
  std::vector<CutCluster>* centred = nullptr;
  const CutNodeTable* cut_nodes = nullptr;
  // When relative: a hash of the point, which draws an exact cluster's shadow ray (keep_cluster),
  // and the scratch that cluster's lights are gathered in.
  std::uint64_t point_seed = 0;
  WalkScratch* scratch = nullptr;
  std::uint64_t lights_evaluated = 0;  // the exact clusters' lights (WalkCounters)
  // The pixel inspector's record (WalkScratch::inspect): what is culled and clustered, when set.
  InspectRecord* record = nullptr;
};

// The inspector's note of a culled subtree, or of a cluster standing for one (its representative
// at `index` of the list the walk appended it to), entered with world_from_local = (linear,
// translation).
void record_culled_subtree(InspectRecord& record, std::uint32_t node, const WalkLinear& linear,
                           const glm::vec3& translation) {
  record.culled_subtrees.push_back(
      {node, Similarity{linear.rotation, linear.scale, translation}, FramePoint{}});
}
void record_subtree_cluster(InspectRecord& record, std::size_t index, std::uint32_t node,
                            const WalkLinear& linear, const glm::vec3& translation) {
  WalkCluster& cluster = record.walk_clusters.emplace_back();
  cluster.index = index;
  cluster.whole_subtree = true;
  cluster.subtree = {node, Similarity{linear.rotation, linear.scale, translation}, FramePoint{}};
}

// The most a cluster's bound (brightest channel) may be at this point of the walk.
inline float largest_cluster_bound(const CulledSoFar& culled) {
  return culled.relative_error * std::max(brightest(culled.total), culled.total_floor);
}

// The sum of culled bounds may grow by `more` and stay within the budget: compared on the scale
// of the per-light test, the brightest channel (light.h), with the tolerance, less room for
// round_up_sum's final rounding so that the float bound returned is within it too.
inline bool fits_budget(const glm::dvec3& culled, const glm::dvec3& more, float budget) {
  const glm::dvec3 sum = culled + more;
  return std::max(std::max(sum.x, sum.y), sum.z) <= static_cast<double>(budget) * (1.0 - 1e-6);
}

// The largest per-channel product a * b of two non-negative bounds, 0 where either is 0 (never
// inf * 0).
inline glm::dvec3 product_bound(const glm::vec3& a, const glm::vec3& b) {
  glm::dvec3 p(0.0);
  for (int c = 0; c < 3; ++c) {
    if (a[c] > 0.0f && b[c] > 0.0f) p[c] = static_cast<double>(a[c]) * static_cast<double>(b[c]);
  }
  return p;
}

// Orders the culled radiance parts' heap: the largest bound on top, the earlier part first.
bool smaller_radiance_part(const RadiancePart& a, const RadiancePart& b) {
  return a.key < b.key || (a.key == b.key && a.sequence > b.sequence);
}

// Adds the subtree at `node` to the radiance parts' heap with its radiance bound at x (both in
// the frame the node is entered with, as the surface's directions), unless it is dark there.
// add_radiance_part takes the bounds made already.
void add_radiance_part(std::uint32_t node, const FramePoint& x, const glm::vec3& normal,
                       const glm::vec3& mirrored_view, const glm::vec3& bound,
                       const glm::vec3& irradiance, CulledSoFar& culled) {
  float key = brightest(bound);
  if (key == 0.0f) {  // dark at this surface, yet its irradiance still counts
    culled.sum += glm::dvec3(irradiance);
    return;
  }
  if (!(key >= 0.0f)) key = std::numeric_limits<float>::infinity();  // NaN: opened first
  culled.radiance_parts->push_back(
      {key, culled.radiance_parts_made++, node, x, normal, mirrored_view, bound, irradiance});
  std::push_heap(culled.radiance_parts->begin(), culled.radiance_parts->end(),
                 smaller_radiance_part);
}
void push_radiance_part(const LightHierarchy& h, std::uint32_t node, const FramePoint& x,
                        const glm::vec3& normal, const glm::vec3& mirrored_view,
                        CulledSoFar& culled) {
  SurfaceResponse surface = culled.radiance->surface;
  surface.normal = normal;
  surface.mirrored_view = mirrored_view;
  glm::vec3 irradiance;
  const glm::vec3 bound = radiance_bound(h, node, x, surface, &irradiance);
  add_radiance_part(node, x, normal, mirrored_view, bound, irradiance, culled);
}

// The exact test of one world-space light (is_important, one falloff for both uses); a light
// that fails it adds its irradiance to `culled`, and under a budget it is kept (it passes) when
// the budget cannot take it.
// Clustered, a culled light bright enough to keep is a cluster of its own.
template <Culled kCulled>
inline bool passes(const Light& world, const glm::vec3& point, float tolerance,
                   CulledSoFar& culled) {
  const float falloff = irradiance_falloff(world, point);
  bool important = is_important_from_falloff(world, falloff, tolerance);
  glm::dvec3 dropped_radiance(0.0);
  if constexpr (kCulled == Culled::relative) {
    if (!important && culled.shading && falloff > 0.0f) {
      // The light's own radiance bound, as the culled radiance bound takes it (below).
      const Bounds at_light{world.position, world.position};
      dropped_radiance =
          product_bound(irradiance_from_falloff(world, falloff),
                        response_bound(culled.surface, at_light, FramePoint{point, 0.0f}));
      important = brightest(culled.dropped + dropped_radiance) > culled.drop_budget;
    }
  }
  if (important) {
    if constexpr (kCulled == Culled::relative) {
      if (culled.shading) {
        const glm::vec3 estimate = culled.shading->unshadowed_radiance(world);
        culled.total += glm::dvec3(estimate);
        culled.estimates->push_back(estimate);
      }
    }
    return true;
  }
  if constexpr (kCulled == Culled::collected) {
    if (falloff > 0.0f) culled.parts->lights.push_back(world);
  } else if constexpr (kCulled != Culled::dropped) {
    const glm::dvec3 e(irradiance_from_falloff(world, falloff));
    if (kCulled == Culled::budgeted && !fits_budget(culled.sum, e, tolerance)) return true;
    culled.sum += e;
    if constexpr (kCulled == Culled::relative) culled.dropped += dropped_radiance;
    if constexpr (kCulled == Culled::tight || kCulled == Culled::relative) {
      // The light's own radiance bound: its exact irradiance times the response toward it, the
      // same floats rt shades (the point's rounding is the response bound's slack).
      if (culled.radiance) {
        const Bounds at_light{world.position, world.position};
        culled.radiance_sum +=
            kCulled == Culled::relative && culled.shading
                ? dropped_radiance
                : product_bound(glm::vec3(e), response_bound(culled.radiance->surface, at_light,
                                                             FramePoint{point, 0.0f}));
      }
    }
    if (kCulled == Culled::clustered && brightest(e) > culled.cut.keep_above) {
      culled.clusters->push_back(world);
      if (culled.record) {
        WalkCluster& cluster = culled.record->walk_clusters.emplace_back();
        cluster.index = culled.clusters->size() - 1;
        cluster.single = world;
      }
      return false;
    }
  }
  if (culled.record) culled.record->culled_lights.push_back(world);
  return false;
}

// One light node: with kCull its exact test (one volume checked), else just its world copy. A
// translation moves a point light and changes nothing else, so such a light is tested before it
// is copied (the same floats as push_world_light's); any other is transformed, then tested.
template <bool kCull, Culled kCulled>
inline void visit_light(const Light& local, const glm::vec3& point, float tolerance,
                        const WalkLinear& linear, bool identity, const glm::vec3& translation,
                        std::vector<Light>& out, std::uint64_t& visited, CulledSoFar& culled) {
  if (identity && local.kind == LightKind::point) {
    Light world = local;
    world.position = local.position + translation;
    if constexpr (kCull) {
      ++visited;
      if (!passes<kCulled>(world, point, tolerance, culled)) return;
    }
    out.emplace_back(local).position = world.position;
    return;
  }
  const Light& world = push_world_light(out, local, linear, identity, translation);
  if constexpr (kCull) {
    ++visited;
    if (!passes<kCulled>(world, point, tolerance, culled)) out.pop_back();
  }
}

// Whether a subtree holds any light (a union may be empty).
bool holds_lights(const LightHierarchy& h, std::uint32_t node) {
  node = pass_transforms(h, node);
  return node_role(h.nodes[node]) == NodeRole::light || !is_empty(kept_aggregate(h, node));
}

// A subtree entered with world_from_local = (linear, translation), moved below its transforms:
// `node` becomes the first other node and `world_from_local` that node's frame. A light there is
// returned in world space: a light below a transform is culled by its box like a subtree and
// stands for itself (representative_light, drawn_representative).
std::optional<Light> light_below_affine(const LightHierarchy& h, std::uint32_t& node,
                                        const WalkLinear& linear, const glm::vec3& translation,
                                        Similarity& world_from_local) {
  world_from_local = Similarity{linear.rotation, linear.scale, translation};
  node = pass_transforms(
      h, node, [&](const HierarchyNode& n) { compose_node_transform(h, n, world_from_local); });
  const HierarchyNode& top = h.nodes[node];
  if (node_role(top) == NodeRole::light)
    return transform_light(leaf_light(h, top), world_from_local);
  return std::nullopt;
}

// The first light of a subtree that holds lights (the lights' order), found down the first child
// that holds any at each union; on_transform(n) is called for each transform passed, top first.
template <typename OnTransform>
std::uint32_t first_light(const LightHierarchy& h, std::uint32_t node, OnTransform&& on_transform) {
  for (;;) {
    node = pass_to_light_or_group(h, node, on_transform);
    const HierarchyNode& n = h.nodes[node];
    if (node_role(n) != NodeRole::group) return node;
    // The subtree holds lights, so one of the children does.
    const std::uint32_t* child = group_children(h, n).begin();
    while (!holds_lights(h, *child)) ++child;
    node = *child;
  }
}

// A culled subtree as one light, its representative (find_lights_and_clusters). Entered with
// world_from_local = (linear, translation). The centre of the positions rather than one of the
// lights: measured in lev_est's selector (selector_lev_est.cpp). `table` (may be null) gives the
// first light when only translations lie below.
Light representative_light(const LightHierarchy& h, const CutNodeTable* table, std::uint32_t node,
                           const WalkLinear& linear, const glm::vec3& translation) {
  Similarity world_from_local;
  if (std::optional<Light> light =
          light_below_affine(h, node, linear, translation, world_from_local)) {
    return *light;
  }
  const LightAggregate& aggregate = kept_aggregate(h, node);  // in the frame just composed
  const Similarity& cluster_from_local = world_from_local;
  // Below, only the first light's parameters are wanted: its frame is composed in full only
  // when its own direction is (the cone of axes is too wide to aim along); else its scale does.
  // Translations change neither, so a first light found in the table leaves both as they are.
  const bool aim_along_cone = aggregate.cos_axis_spread > 0.0f;
  Similarity light_from_local = cluster_from_local;
  float scale = cluster_from_local.scale;
  std::uint32_t first = table ? table->first_lights[node] : kNoNode;
  if (first == kNoNode) {
    first = first_light(h, node, [&](const HierarchyNode& n) {
      scale *= node_transform(h, n).scale;
      if (!aim_along_cone) compose_node_transform(h, n, light_from_local);
    });
  }
  Light representative = leaf_light(h, h.nodes[first]);
  if (aim_along_cone) {
    representative.range *= scale;
    if (representative.kind == LightKind::spot) {
      representative.direction =
          glm::normalize(apply_direction(cluster_from_local, aggregate.axis));
    }
  } else {
    representative = transform_light(representative, light_from_local);
  }
  representative.intensity =
      aggregate.intensity * (cluster_from_local.scale * cluster_from_local.scale);
  representative.position =
      apply_point(cluster_from_local, 0.5f * (aggregate.positions.lo + aggregate.positions.hi));
  return representative;
}

// A subtree whose volume missed the point, the walk's point in the frame (linear, translation) it
// is entered with (point_magnitude is max_abs(world point)): its aggregate bound is summed into
// `culled` unless the walk drops what it culls.
// True when the subtree is culled: always unless under a budget its bound does not fit, or,
// clustered, its bound is above the cut's refine_above (then it is walked, its parts culled).
template <Culled kCulled>
inline bool cull_subtree(const LightHierarchy& h, std::uint32_t node, const glm::vec3& local_point,
                         float point_magnitude, const glm::vec3& translation,
                         const WalkLinear& linear, float tolerance, CulledSoFar& culled) {
  if constexpr (kCulled == Culled::dropped) {
    if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
    return true;
  }
  if constexpr (kCulled == Culled::collected) {
    culled.parts->subtrees.push_back(
        {node, Similarity{linear.rotation, linear.scale, translation},
         walk_frame_point(local_point, point_magnitude, translation, linear.scale)});
    if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
    return true;
  }
  const FramePoint x = walk_frame_point(local_point, point_magnitude, translation, linear.scale);
  if constexpr (kCulled == Culled::tight) {
    if (culled.radiance) {
      // Its irradiance is summed with its parts' once they are settled (answer_culled_radiance).
      const glm::mat3 local_from_world = glm::transpose(linear.rotation);
      push_radiance_part(h, node, x, local_from_world * culled.radiance->surface.normal,
                         local_from_world * culled.radiance->surface.mirrored_view, culled);
    } else {
      culled.sum += tightened_irradiance_bound(h, node, x, tolerance, culled.openings_left,
                                               *culled.bound_parts);
    }
    if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
    return true;
  }
  if constexpr (kCulled == Culled::relative) {
    if (culled.shading) {  // cutting: what it drops is within the drop budget, or it is cut
      const SurfaceResponse surface = surface_in_frame(culled.surface, linear.rotation);
      glm::vec3 irradiance;
      const glm::vec3 radiance = radiance_bound(h, node, x, surface, &irradiance);
      if (brightest(culled.dropped + glm::dvec3(radiance)) > culled.drop_budget) return false;
      culled.dropped += glm::dvec3(radiance);
      if (culled.radiance) {  // the same bounds (culled.surface is the point's surface too)
        add_radiance_part(node, x, surface.normal, surface.mirrored_view, radiance, irradiance,
                          culled);
      } else {
        culled.sum += glm::dvec3(irradiance);
      }
      if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
      return true;
    }
    if (culled.radiance) {  // as tight's: bounded, and opened, at the surface once the walk ends
      const glm::mat3 local_from_world = glm::transpose(linear.rotation);
      push_radiance_part(h, node, x, local_from_world * culled.radiance->surface.normal,
                         local_from_world * culled.radiance->surface.mirrored_view, culled);
      if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
      return true;
    }
  }
  const glm::dvec3 b(irradiance_bound(h, node, x));
  if (kCulled == Culled::budgeted && !fits_budget(culled.sum, b, tolerance)) return false;
  if constexpr (kCulled == Culled::clustered) {
    const float brightest_bound = brightest(b);
    if (!(brightest_bound <= culled.cut.refine_above)) return false;  // NaN-safe: +inf refines
    if (brightest_bound > culled.cut.keep_above) {
      culled.clusters->push_back(representative_light(h, nullptr, node, linear, translation));
      if (culled.record) {
        record_subtree_cluster(*culled.record, culled.clusters->size() - 1, node, linear,
                               translation);
      }
      culled.sum += b;
      return true;
    }
  }
  culled.sum += b;
  if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
  return true;
}

// A culled part whose radiance bound is at most this share of the tolerance is not opened: it
// adds little to the point's bound, and opening it costs as much as a larger one (building 256 at
// 0.01: the same bounds as with 1/256, fewer parts opened).
constexpr float kRadianceOpenedAboveShareOfTolerance = 1.0f / 64.0f;

// The culled radiance bound's answer (CulledRadianceBound), once the walk is done: the culled
// lights' bounds plus the culled subtrees', each opened best first (the part with the largest
// bound next) while it is brighter than the tolerance's share above and unions may still be
// opened (kRadianceOpeningsPerPoint); a part left unopened keeps its certified cluster bound.
void answer_culled_radiance(const LightHierarchy& h, float tolerance, CulledSoFar& culled) {
  std::vector<RadiancePart>& parts = *culled.radiance_parts;
  const float open_above = tolerance * kRadianceOpenedAboveShareOfTolerance;
  int openings_left = kRadianceOpeningsPerPoint;
  glm::dvec3 sum = culled.radiance_sum;
  while (!parts.empty()) {
    if (openings_left <= 0 || !(parts.front().key > open_above)) {
      for (const RadiancePart& rest : parts) {
        sum += glm::dvec3(rest.bound);
        culled.sum += glm::dvec3(rest.irradiance);
      }
      break;
    }
    std::pop_heap(parts.begin(), parts.end(), smaller_radiance_part);
    RadiancePart part = parts.back();
    parts.pop_back();
    // Down to the light or union the part stands for, its point and surface moved along.
    part.node = pass_to_light_or_group(h, part.node, [&](const HierarchyNode& n) {
      enter_transform(h, n, part.point, part.normal, part.mirrored_view);
    });
    const HierarchyNode& n = h.nodes[part.node];
    if (node_role(n) == NodeRole::light) {  // its bounds are its own
      sum += glm::dvec3(part.bound);
      culled.sum += glm::dvec3(part.irradiance);
      continue;
    }
    --openings_left;
    for (const std::uint32_t child : group_children(h, n))
      push_radiance_part(h, child, part.point, part.normal, part.mirrored_view, culled);
  }
  parts.clear();
  culled.radiance->bound = round_up_sum(sum);
  culled.radiance->bounded = true;
}

// The intensity (draw_weight) of the lights of the subtree at `node`, in the frame it is entered
// with: a transform's child's times its scale squared.
double subtree_weight(const LightHierarchy& h, std::uint32_t node) {
  double scale2 = 1.0;
  node = pass_transforms(h, node, [&](const HierarchyNode& n) {
    const double s = node_transform(h, n).scale;
    scale2 *= s * s;
  });
  const HierarchyNode& n = h.nodes[node];
  if (node_role(n) == NodeRole::light) return scale2 * draw_weight(leaf_light(h, n).intensity);
  return scale2 * draw_weight(kept_aggregate(h, node).intensity);
}

// One light of the subtree at `node`, entered with world_from_local, drawn down the subtree: at
// each union a child with probability proportional to its intensity (subtree_weight) by
// node_uniform of the union's index shifted by `shift` (mod 1), so each light is drawn with
// probability proportional to its intensity and the draw is fixed for the scene. Returns the
// light's node; world_from_local becomes its frame, and `transformed` (when given) is set if a
// transform was passed on the way.
std::uint32_t draw_light(const LightHierarchy& h, const CutNodeTable& table, std::uint32_t node,
                         Similarity& world_from_local, double shift, bool* transformed = nullptr) {
  for (;;) {
    node = pass_to_light_or_group(h, node, [&](const HierarchyNode& n) {
      compose_node_transform(h, n, world_from_local);
      if (transformed) *transformed = true;
    });
    const HierarchyNode& n = h.nodes[node];
    if (node_role(n) == NodeRole::light) return node;
    const ChildNodes children = group_children(h, n);
    double total = 0.0;
    for (const std::uint32_t child : children) total += table.draw_weights[child];
    const double u = node_uniform(node) + shift;
    double left = (u - std::floor(u)) * total;
    std::uint32_t chosen = kNoNode;
    for (const std::uint32_t child : children) {
      const double w = table.draw_weights[child];
      if (w <= 0.0) continue;  // an empty union weighs 0 too
      chosen = child;
      if (left < w) break;
      left -= w;
    }
    // Every light below is dark (intensity 0; the node table draws from every union): its first
    // child with a light. It was node 0, the root, and the draw began again there for ever.
    if (chosen == kNoNode) {
      for (const std::uint32_t child : children) {
        if (holds_lights(h, child)) {
          chosen = child;
          break;
        }
      }
    }
    assert(chosen != kNoNode);  // the subtree holds lights, so one child does
    node = chosen;
  }
}

// A kept subtree as one of its own lights, Lightcuts' representative (Walter et al. 2005, sec.
// 4.1) in world space, carrying the subtree's summed intensity: drawn by draw_light (unshifted).
// Not lev_est's centre of the box aimed along the cone axis: a relative cut keeps large
// clusters, where that light's bias adds up the same way in every cluster (stage 4,608, 80x60,
// relative error 0.02: avg / max error 2.36 / 27.2 % with it). Entered with world_from_local =
// (linear, translation).
Light drawn_representative(const LightHierarchy& h, const CutNodeTable& table, std::uint32_t node,
                           const WalkLinear& linear, const glm::vec3& translation) {
  Similarity world_from_local;
  if (std::optional<Light> light =
          light_below_affine(h, node, linear, translation, world_from_local)) {
    return *light;
  }
  const glm::vec3 intensity =
      kept_aggregate(h, node).intensity * (world_from_local.scale * world_from_local.scale);
  // The draw made once (CutNodeTable) when no transform lies below: world_from_local stays.
  std::uint32_t drawn = table.drawn_lights[node];
  if (drawn == kNoNode) drawn = draw_light(h, table, node, world_from_local, 0.0);
  const Light& leaf = leaf_light(h, h.nodes[drawn]);
  Light representative;
  if (world_from_local.scale == 1.0f && world_from_local.rotation == glm::mat3(1.0f)) {
    // transform_light's floats without the products by one and zero (as push_world_light).
    representative = leaf;
    representative.position = leaf.position + world_from_local.translation;
    if (leaf.kind == LightKind::spot) representative.direction = glm::normalize(leaf.direction);
  } else {
    representative = transform_light(leaf, world_from_local);
  }
  representative.intensity = intensity;
  return representative;
}

// How far a cluster's spot axes may spread, as a share of the angle its spots shine into, for
// lev_est's representative (the centre of the box, aimed along the cone axis) to stand for it.
constexpr float kCentredSpreadOfEmission = 0.25f;

// Whether lev_cut stands for a kept subtree of several lights by lev_est's centred representative:
// where the lights shine everywhere (point lights) or their axes spread little against their
// cones (a spot split in four: the hall); else by a drawn one (spots aimed apart, where a light
// aimed along the mean axis lights what none of them lights: the stage). Measured at 80x60,
// relative error 0.02, avg / max error against rt: stage 4,608 centred 2.36 / 27.2 %, drawn 0.55
// / 8.4 %; hall 4,096 drawn 0.85 / 10.1 %. A single light below transforms stands for itself.
bool centred_cluster(const LightHierarchy& h, std::uint32_t node) {
  const std::uint32_t below = pass_transforms(h, node);
  if (node_role(h.nodes[below]) == NodeRole::light) return false;
  const LightAggregate& a = kept_aggregate(h, below);
  return shines_everywhere(a) ||
         std::acos(std::clamp(a.cos_axis_spread, -1.0f, 1.0f)) <=
             kCentredSpreadOfEmission * std::acos(std::clamp(a.cos_emission, -1.0f, 1.0f));
}

// The centred cluster's shadow ray (CutCluster) goes to one of its lights, not to the centre: the
// centre is where no light is, so what hides the lights themselves (their own cans, on the hall's
// rig) hides no ray to it, and what stands between them hides rays to it that the lights pass;
// its visibility was wrong the same way in every cluster, and a finer cut did not shrink that
// (hall 16,384, 80x60: max error 3.66 % at relative error 0.02, 4.84 % at 0.01). The light is
// drawn in proportion to intensity (draw_light), so its visibility is the cluster's on average,
// shifted by a hash of the translation the cluster's lights are placed with: the instances of one
// master (every fixture of the rig) draw different lights, whose errors then do not add up alike.
double cluster_draw_shift(const glm::vec3& world_translation) {
  std::uint32_t bits[3];
  std::memcpy(bits, &world_translation, sizeof bits);
  return node_uniform(bits[0] ^ (bits[1] * 0x9E3779B9u) ^ (bits[2] * 0x85EBCA6Bu));
}

// The most lights a cluster of the relative cut with a drawn representative may hold to be
// shaded from its own lights instead (keep_cluster).
constexpr std::uint32_t kExactClusterLights = 32;

// The seed of an exact cluster's draw at this point (keep_cluster): a hash of the point, the
// cluster's node and the translation its lights are placed with (the instances of one master draw
// apart), so the draw depends on the point alone, never on the thread or the tile order.
std::uint64_t exact_cluster_seed(std::uint64_t point_seed, std::uint32_t node,
                                 const glm::vec3& translation) {
  std::uint32_t bits[3];
  std::memcpy(bits, &translation, sizeof bits);
  return point_seed ^ (static_cast<std::uint64_t>(node) * 0x9E3779B97F4A7C15ull) ^
         (static_cast<std::uint64_t>(bits[0]) << 32 | bits[1]) * 0xD6E8FEB86659FD93ull ^
         static_cast<std::uint64_t>(bits[2]) * 0xFF51AFD7ED558CCDull;
}

std::uint64_t point_hash(const glm::vec3& point) {
  std::uint32_t bits[3];
  std::memcpy(bits, &point, sizeof bits);
  return (static_cast<std::uint64_t>(bits[0]) << 32 | bits[1]) * 0x9E3779B97F4A7C15ull ^
         static_cast<std::uint64_t>(bits[2]) * 0xC2B2AE3D27D4EB4Full;
}

// A subtree of the relative cut kept as one cluster (within the criterion), entered with
// world_from_local = (linear, translation): appended to `out` with its unshadowed estimate, its
// bounds summed. `estimate` is its representative's, which the running total counted.
//
// A cluster of at most kExactClusterLights lights that a drawn representative would stand for
// (spots aimed apart) is an exact cluster: shaded from its own lights. Its estimate is their
// summed unshadowed radiance (the running total takes it instead of the representative's), and
// its shadow ray goes to one of them drawn in proportion to its unshadowed radiance at the point
// (exact_cluster_seed), so the visibility is the cluster's on average and the error left is
// visibility's alone. A drawn representative's unshadowed radiance is wrong where its spots aim
// apart (one whose cone misses the point stands for others that light it, and the reverse), and
// hundreds of such clusters add up alike over a region: on stage 4,608 at relative error 0.01,
// at pixel (252, 140), 70 % of the pixel's -5.9 % error. Measured on the stage (320x240, one
// pixel in 16, against rt): at 0.01 avg / max error 0.330 / 5.88 % before, 0.078 / 1.57 % after,
// for 1.51x the selector's instructions (docs/results/lev_cut.md). A centred representative's
// unshadowed radiance is close to its lights' sum (the hall), so those stay as they were. An
// exact cluster whose lights give nothing here is dropped (no ray).
void keep_cluster(const LightHierarchy& h, const CutSubtree& subtree, const Light& representative,
                  std::vector<Light>& out, CulledSoFar& culled) {
  const std::uint32_t node = subtree.node;
  const WalkLinear& linear = subtree.linear;
  const glm::vec3& translation = subtree.world_translation;
  glm::vec3 estimate = subtree.estimate;
  bool several = culled.cut_nodes->light_counts[node] >= 2;
  if (!subtree.centred && culled.cut_nodes->light_counts[node] <= kExactClusterLights) {
    // One pass: the summed radiance, and the ray's light by weighted reservoir sampling (each
    // light kept with its weight over the weight so far), one draw of the cluster's stream (the
    // renderer's splitmix64, RandomStream) per lit light.
    RandomStream stream{exact_cluster_seed(culled.point_seed, node, translation)};
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    std::uint32_t lit = 0;
    Light& chosen = culled.scratch->cluster_light;
    for_each_subtree_light(h, node, Similarity{linear.rotation, linear.scale, translation},
                           culled.scratch->subtree_parts, [&](const Light& light) {
                             ++culled.lights_evaluated;
                             const glm::vec3 r = culled.shading->unshadowed_radiance(light);
                             const double w = draw_weight(r);
                             if (!(w > 0.0)) return true;
                             sum += glm::dvec3(r);
                             weight += w;
                             ++lit;
                             if (stream.next_double() * weight < w) chosen = light;
                             return true;
                           });
    culled.total += sum - glm::dvec3(estimate);
    if (lit == 0) {  // dark here: nothing to shade
      if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
      return;
    }
    estimate = glm::vec3(glm::min(sum, glm::dvec3(std::numeric_limits<float>::max())));
    out.push_back(chosen);
    culled.scratch->exact_clusters.push_back(out.size() - 1);
    several = lit >= 2;
  } else {
    out.push_back(representative);
    if (subtree.centred) culled.centred->push_back({out.size() - 1, node, linear, translation});
  }
  culled.estimates->push_back(estimate);
  if (several) culled.scratch->several_light_clusters.push_back(out.size() - 1);
  if (culled.record)
    record_subtree_cluster(*culled.record, out.size() - 1, node, linear, translation);
  culled.cluster_sum += glm::dvec3(subtree.irradiance_bound);
  culled.cluster_error += glm::dvec3(glm::max(estimate, subtree.radiance_bound));
  if (culled.kept) {
    CutSubtree& kept = culled.kept->emplace_back(subtree);
    kept.estimate = estimate;
    kept.kept_as = static_cast<std::uint32_t>(out.size() - 1);
    kept.several = several;
  }
}

// A cluster of the cut before kept again by a finer one (refine_light_cut): its light (the
// representative, or an exact cluster's light drawn) and its estimate are the ones that cut
// made, so it costs no work, and it is listed and summed as keep_cluster lists and sums it.
void keep_cluster_again(const CutSubtree& subtree, std::vector<Light>& out, CulledSoFar& culled) {
  WalkScratch& scratch = *culled.scratch;
  const std::uint32_t node = subtree.node;
  out.push_back(scratch.previous_lights[subtree.kept_as]);
  const std::size_t index = out.size() - 1;
  if (subtree.centred) {
    culled.centred->push_back({index, node, subtree.linear, subtree.world_translation});
  } else if (culled.cut_nodes->light_counts[node] <= kExactClusterLights) {
    scratch.exact_clusters.push_back(index);
  }
  culled.estimates->push_back(subtree.estimate);
  if (subtree.several) scratch.several_light_clusters.push_back(index);
  if (culled.record)
    record_subtree_cluster(*culled.record, index, node, subtree.linear, subtree.world_translation);
  culled.cluster_sum += glm::dvec3(subtree.irradiance_bound);
  culled.cluster_error += glm::dvec3(glm::max(subtree.estimate, subtree.radiance_bound));
  if (culled.kept) culled.kept->emplace_back(subtree).kept_as = static_cast<std::uint32_t>(index);
}

// The relative cut's decision on a subtree the volumes kept (find_light_cut), entered with
// world_from_local = (linear, translation) and the walk's point local_point in that frame: it is
// dark at the point (bound 0: nothing to add), or it joins the cut as a cluster, its
// representative's unshadowed radiance added to the total, and stays one (its representative
// appended to `out`) when its bound is within the criterion, else is put aside in `deferred`
// (resume_deferred). It is never walked from here.
inline void cut_or_defer(const LightHierarchy& h, std::uint32_t node, const glm::vec3& local_point,
                         float point_magnitude, const glm::vec3& translation,
                         const WalkLinear& linear, bool identity, bool volume_tested,
                         std::vector<Light>& out, std::vector<DeferredSubtree>& deferred,
                         std::vector<DeferredKey>& heap, CulledSoFar& culled) {
  const FramePoint x = walk_frame_point(local_point, point_magnitude, translation, linear.scale);
  const SurfaceResponse surface =
      identity ? culled.surface : surface_in_frame(culled.surface, linear.rotation);
  glm::vec3 irradiance;
  const glm::vec3 radiance = radiance_bound(h, node, x, surface, &irradiance);
  float bound = brightest(radiance);
  if (bound == 0.0f) {  // dark here: culled
    if (culled.record) record_culled_subtree(*culled.record, node, linear, translation);
    return;
  }
  if (!(bound >= 0.0f)) bound = std::numeric_limits<float>::infinity();  // NaN: walk it first
  const bool centred = culled.cut_nodes->centred[node] != 0;
  const Light representative = culled.scratch->representatives.find_or_make(
      node, linear.rotation, linear.scale, translation, [&] {
        return centred ? representative_light(h, culled.cut_nodes, node, linear, translation)
                       : drawn_representative(h, *culled.cut_nodes, node, linear, translation);
      });
  const glm::vec3 estimate = culled.shading->unshadowed_radiance(representative);
  culled.total += glm::dvec3(estimate);
  const bool keep = bound <= largest_cluster_bound(culled);
  if (!keep) {
    heap.push_back({bound, culled.deferrals++, static_cast<std::uint32_t>(deferred.size())});
    std::push_heap(heap.begin(), heap.end(), smaller_deferred_bound);
  }
  CutSubtree kept_here;
  DeferredSubtree* put_aside = keep ? nullptr : &deferred.emplace_back();
  CutSubtree& d = put_aside ? *put_aside : kept_here;
  d.node = node;
  d.volume_tested = volume_tested;
  d.identity = identity;
  d.centred = centred;
  d.local_point = local_point;
  d.world_translation = translation;
  d.linear = linear;
  d.estimate = estimate;
  d.irradiance_bound = irradiance;
  d.radiance_bound = radiance;
  if (put_aside) {
    put_aside->representative = representative;
  } else {
    keep_cluster(h, d, representative, out, culled);
  }
}

// The translation of compose(world_from_local, xf), world_from_local = (linear, translation).
inline glm::vec3 compose_translation(const std::vector<WalkLinear>& linear,
                                     std::uint32_t linear_index, const glm::vec3& xf_translation,
                                     const glm::vec3& translation) {
  if (linear_index == 0) return xf_translation + translation;
  const WalkLinear& outer = linear[linear_index];
  return outer.rotation * (outer.scale * xf_translation) + translation;
}

// The relative cut, when the walk has nothing left on its stack: the subtree put aside with the
// largest bound stays a cluster (its representative appended to `out`) if the total allows it,
// else it leaves the cut's total and goes on the stack, in its own frame, to be walked. False
// when none is left.
bool resume_deferred(const LightHierarchy& h, std::vector<WalkFrame>& stack,
                     std::vector<WalkLinear>& linear, const std::vector<DeferredSubtree>& deferred,
                     std::vector<DeferredKey>& heap, std::vector<Light>& out, CulledSoFar& culled) {
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), smaller_deferred_bound);
    const DeferredKey key = heap.back();
    heap.pop_back();
    const DeferredSubtree& d = deferred[key.subtree];
    if (key.bound <= largest_cluster_bound(culled)) {
      if (d.kept_as != CutSubtree::kNotKept) {
        keep_cluster_again(d, out, culled);
      } else {
        keep_cluster(h, d, d.representative, out, culled);
      }
      continue;
    }
    culled.total -= glm::dvec3(d.estimate);
    // The stack is empty, so the frames' rotations are all free: only this one's is kept.
    linear.resize(1);
    if (!d.identity) linear.push_back(d.linear);
    push_frame(stack, d.local_point, d.node, d.world_translation, d.identity ? 0 : 1,
               d.volume_tested);
    return true;
  }
  return false;
}

// One walk for both the query (cull = true) and the flattening (cull = false): sharing it is what
// makes `lev` at tolerance 0 and `rt` see bit-identical world-space lights.
//
// Culling happens as early as possible: a union tests each child's box (which every node keeps
// in the frame it is entered with) before pushing it, so a culled child costs one box test, no
// frame and no transform composition (thesis fig. 3.5 tests the volumes the same way, one level
// earlier). The box a child passed at the union is, up to padding, the box of the first node
// with a volume inside it (moved by a translation), so that node does not test it again.
// Unless kCulled is `dropped` every cull also adds what it dropped to the culled irradiance bound;
// under a budget a subtree that does not fit is walked as if its volume held the point.
// Clustered, the subtrees culled with a bound above the cut's refine_above are walked too, so
// that what is culled comes in parts no brighter than that.
template <bool kCull, Culled kCulled, typename Nodes>
void walk(const LightHierarchy& h, const Nodes nodes, const float tolerance, const glm::vec3& point,
          WalkScratch& scratch, std::vector<Light>& out, WalkCounters& counters,
          glm::vec3* culled_irradiance_bound, CulledSoFar culled = {}) {
  std::vector<WalkFrame>& stack = scratch.stack;
  std::vector<WalkLinear>& linear = scratch.linear;
  std::uint64_t visited = 0;  // a local, so the compiler need not store it through every write
  const float point_magnitude = max_abs(point);
  stack.clear();
  linear.clear();
  linear.emplace_back();
  std::vector<DeferredSubtree>& deferred = scratch.deferred;
  std::vector<DeferredKey>& deferred_heap = scratch.deferred_heap;
  if (!culled.go_on) {
    push_frame(stack, point, h.root, glm::vec3(0.0f), 0, false);
    deferred.clear();
    deferred_heap.clear();
  }
  culled.record = scratch.inspect;
  for (;;) {
    if (stack.empty()) {
      if constexpr (kCulled != Culled::relative) break;
      if (!resume_deferred(h, stack, linear, deferred, deferred_heap, out, culled)) break;
    }
    const WalkFrame& top = stack.back();
    glm::vec3 local_point = top.local_point;
    std::uint32_t index = top.node;
    glm::vec3 translation = top.world_translation;
    std::uint32_t linear_index = top.linear;
    bool volume_tested = top.volume_tested;
    stack.pop_back();
    // Linear indices never decrease up the stack, so nothing below this frame needs a later one.
    linear.resize(linear_index + 1);
    for (;;) {
      const HierarchyNode& node = nodes.node(index);
      bool descend = false;
      switch (node_role(node)) {
        case NodeRole::light:
          visit_light<kCull, kCulled>(leaf_light(h, node), point, tolerance, linear[linear_index],
                                      linear_index == 0, translation, out, visited, culled);
          break;
        case NodeRole::transform: {
          const Similarity& xf = node_transform(h, node);
          const bool translation_only = is_translation_only(node);
          // compose(world_from_local, xf), in two parts.
          translation = compose_translation(linear, linear_index, xf.translation, translation);
          if (!translation_only) {
            const WalkLinear outer = linear[linear_index];
            WalkLinear& inner = linear.emplace_back();
            inner.rotation = outer.rotation * xf.rotation;
            inner.scale = outer.scale * xf.scale;
            linear_index = static_cast<std::uint32_t>(linear.size() - 1);
            // Only a translation keeps the child's box the parent's test stood for.
            volume_tested = false;
          }
          if constexpr (kCull) {
            local_point = translation_only ? local_point - xf.translation
                                           : apply_inverse_point(xf, local_point);
          }
          index = only_child(node, index);
          descend = true;
          break;
        }
        case NodeRole::bounded:
          if constexpr (kCull) {
            if (volume_tested) {
              volume_tested = false;
            } else {
              ++visited;
              if (!contains(nodes.volume(index), local_point) &&
                  cull_subtree<kCulled>(h, index, local_point, point_magnitude, translation,
                                        linear[linear_index], tolerance, culled)) {
                break;
              }
            }
          }
          index = only_child(node, index);
          descend = true;
          break;
        case NodeRole::reference:
          index = only_child(node, index);
          descend = true;
          break;
        case NodeRole::group: {
          const ChildNodes children = group_children(h, node);
          const std::uint32_t count = children.count;
          // Leading light children are decided here rather than each pushed as a frame: nothing
          // else of this subtree comes before them, so the order is the same.
          std::uint32_t first_pending = 0;
          for (; first_pending < count; ++first_pending) {
            const HierarchyNode& c = nodes.node(children[first_pending]);
            if (node_role(c) != NodeRole::light) break;
            visit_light<kCull, kCulled>(leaf_light(h, c), point, tolerance, linear[linear_index],
                                        linear_index == 0, translation, out, visited, culled);
          }
          // The first child that passes is walked right away; the later ones are pushed
          // last-first so that they come off the stack in order (depth-first, left to right).
          // (Plain locals, not frame structs: a struct assembled field by field and then copied
          // whole stalls on store forwarding.)
          glm::vec3 first_point(0.0f), first_translation(0.0f);
          std::uint32_t first = kNoNode;
          bool first_tested = false;
          for (std::uint32_t k = count; k-- > first_pending;) {
            glm::vec3 child_point = local_point, child_translation = translation;
            std::uint32_t child = children[k];
            bool tested = false;
            if constexpr (kCull) {
              const HierarchyNode& c = nodes.node(child);
              const NodeRole role = node_role(c);
              // Lights get their exact test instead; a union's box is only its children's.
              if (role != NodeRole::light && role != NodeRole::group) {
                ++visited;
                if (!contains(nodes.volume(child), local_point) &&
                    cull_subtree<kCulled>(h, child, local_point, point_magnitude, translation,
                                          linear[linear_index], tolerance, culled)) {
                  continue;
                }
                // Passed, or walked anyway under the budget: the child need not test its box again.
                tested = true;
              }
              if constexpr (kCulled == Culled::relative) {
                if (culled.shading && role != NodeRole::light) {
                  ++visited;
                  cut_or_defer(h, child, local_point, point_magnitude, translation,
                               linear[linear_index], linear_index == 0, tested, out, deferred,
                               deferred_heap, culled);
                  continue;
                }
              }
              // The instancing pattern, translation -> instance -> master, is entered here in one
              // step rather than node by node: the same arithmetic as the affine case, and the
              // master's test is the one just made (up to padding).
              if (role == NodeRole::transform && is_translation_only(c)) {
                const HierarchyNode& below = nodes.node(only_child(c, child));
                if (node_role(below) == NodeRole::reference) {
                  const glm::vec3& t = node_transform(h, c).translation;
                  child_translation = compose_translation(linear, linear_index, t, translation);
                  child_point = local_point - t;
                  child = below_referenced_master(below);
                  tested = false;
                }
              }
            }
            if (first != kNoNode) {
              push_frame(stack, first_point, first, first_translation, linear_index, first_tested);
            }
            first_point = child_point;
            first_translation = child_translation;
            first = child;
            first_tested = tested;
          }
          if (first != kNoNode) {
            local_point = first_point;
            index = first;
            translation = first_translation;
            volume_tested = first_tested;
            descend = true;
          }
          break;
        }
      }
      if (!descend) break;
    }
  }
  counters.nodes_visited += visited;
  counters.lights_evaluated += culled.lights_evaluated;
  if constexpr (kCulled == Culled::relative) {
    // Answered once the cut is final (answer_light_cut_bounds): a finer one may go on from it.
    LightCutSums& sums = culled.scratch->cut_sums;
    sums.total = culled.total;
    sums.culled = culled.sum;
    sums.clusters = culled.cluster_sum;
    sums.cluster_error = culled.cluster_error;
    sums.radiance_culled = culled.radiance_sum;
    sums.radiance_parts_made = culled.radiance_parts_made;
    sums.deferrals = culled.deferrals;
    sums.radiance = culled.radiance != nullptr;
    sums.dropped = culled.dropped;
    sums.drop_budget = culled.drop_budget;
    sums.total_floor = culled.total_floor;
    (void)culled_irradiance_bound;
  } else {
    if constexpr (kCulled == Culled::tight) {
      if (culled.radiance) answer_culled_radiance(h, tolerance, culled);
    }
    if constexpr (kCulled != Culled::dropped && kCulled != Culled::collected) {
      *culled_irradiance_bound = round_up_sum(culled.sum);
    }
  }
}

}  // namespace

namespace {

// The lights below each node, instances expanded, saturating at the largest uint32. Each master's
// range is swept backwards (a node's children follow it), masters in definition order (a master
// precedes those that instance it), so every count is known before a node reads it.
std::vector<std::uint32_t> subtree_light_counts(const LightHierarchy& h) {
  std::vector<std::uint32_t> counts(h.nodes.size(), 0);
  for (const NodeRange& range : h.master_ranges) {
    for (std::uint32_t i = range.end; i-- > range.begin;) {
      const HierarchyNode& n = h.nodes[i];
      std::uint64_t count = 0;
      if (node_role(n) == NodeRole::light) {
        count = 1;
      } else if (node_role(n) == NodeRole::group) {
        for (const std::uint32_t child : group_children(h, n)) count += counts[child];
      } else {
        count = counts[only_child(n, i)];
      }
      counts[i] = static_cast<std::uint32_t>(
          std::min<std::uint64_t>(count, std::numeric_limits<std::uint32_t>::max()));
    }
  }
  assert(h.nodes.empty() ||
         counts[h.root] ==
             std::min<std::uint64_t>(h.light_count, std::numeric_limits<std::uint32_t>::max()));
  return counts;
}

// Whether the lights below each node shine alike (kind, cone, dropoff, profile and range, in
// their own frames), swept as subtree_light_counts is: a centred representative takes its first
// light's, so a subtree mixing a point light and a spot shone the spot's intensity everywhere
// (classteam D1), and one mixing ranges went dark, or lit, with its first light's range.
std::vector<std::uint8_t> subtree_shines_alike(const LightHierarchy& h) {
  std::vector<std::uint8_t> alike(h.nodes.size(), 1);
  std::vector<std::uint32_t> first(h.nodes.size(), kNoNode);
  const auto same = [](const Light& a, const Light& b) {
    return a.kind == b.kind && a.cos_cone_half_angle == b.cos_cone_half_angle &&
           a.dropoff == b.dropoff && a.cos_inner_cone == b.cos_inner_cone &&
           a.profile == b.profile && a.range == b.range;
  };
  for (const NodeRange& range : h.master_ranges) {
    for (std::uint32_t i = range.end; i-- > range.begin;) {
      const HierarchyNode& n = h.nodes[i];
      if (node_role(n) == NodeRole::light) {
        first[i] = n.payload;
      } else if (node_role(n) == NodeRole::group) {
        for (const std::uint32_t child : group_children(h, n)) {
          if (first[child] == kNoNode) continue;
          if (!alike[child]) alike[i] = 0;
          if (first[i] == kNoNode) {
            first[i] = first[child];
          } else if (!same(h.lights[first[i]], h.lights[first[child]])) {
            alike[i] = 0;
          }
        }
      } else {
        alike[i] = alike[only_child(n, i)];
        first[i] = first[only_child(n, i)];
      }
    }
  }
  return alike;
}

}  // namespace

CutNodeTable make_cut_node_table(const LightHierarchy& h) {
  CutNodeTable table;
  const std::size_t count = h.nodes.size();
  table.draw_weights.resize(count);
  table.centred.resize(count);
  table.drawn_lights.resize(count);
  table.first_lights.resize(count);
  table.light_counts = subtree_light_counts(h);
  const std::vector<std::uint8_t> alike = subtree_shines_alike(h);
  for (std::size_t node = 0; node < count; ++node) {
    const auto i = static_cast<std::uint32_t>(node);
    table.draw_weights[node] = subtree_weight(h, i);
    table.drawn_lights[node] = kNoNode;
    table.first_lights[node] = kNoNode;
    // A light has no cluster; a transform's is the node below it, as the walk enters it. A
    // subtree of at most kExactClusterLights whose lights do not shine alike is not centred: an
    // exact cluster, shaded from its own lights (classteam's lamps of a bulb and a spot: avg / max
    // error 3.74 / 6.01 % at relative error 0.02, every pixel too bright; 0.007 / 0.39 % now;
    // ranges.json, lights of five ranges: 0.214 / 4.84 %, 0 / 0.26 % now). A
    // larger one stays centred, its representative's kind its first light's: one per kind would
    // mend that (classteam's deepnest, a million such lamps, errs 3.2 / 26 % still).
    table.centred[node] = node_role(h.nodes[node]) != NodeRole::light &&
                          (alike[node] || table.light_counts[node] > kExactClusterLights) &&
                          centred_cluster(h, i);
  }
  // After every weight is known: draw_light reads them. A draw that passes a transform is made
  // per cluster instead (its frame is composed on the way down).
  for (std::size_t node = 0; node < count; ++node) {
    const auto i = static_cast<std::uint32_t>(node);
    const NodeRole role = node_role(h.nodes[node]);
    if (role == NodeRole::light || role == NodeRole::transform || !holds_lights(h, i)) continue;
    Similarity unused;
    bool transformed = false;
    const std::uint32_t drawn = draw_light(h, table, i, unused, 0.0, &transformed);
    if (!transformed) table.drawn_lights[node] = drawn;
    bool rotated_or_scaled = false;
    const std::uint32_t first = first_light(h, i, [&](const HierarchyNode& n) {
      if (!is_translation_only(n)) rotated_or_scaled = true;
    });
    if (!rotated_or_scaled) table.first_lights[node] = first;
  }
  return table;
}

Light cluster_shadow_target(const LightHierarchy& h, const CutNodeTable& table,
                            const CutCluster& cluster) {
  Similarity world_from_local{cluster.linear.rotation, cluster.linear.scale, cluster.translation};
  // The shift is that of the frame the subtree's lights are placed in: below its own transforms,
  // where each instance of a master has its own translation.
  const std::uint32_t placed = pass_transforms(h, cluster.node, [&](const HierarchyNode& n) {
    compose_node_transform(h, n, world_from_local);
  });
  const std::uint32_t drawn = draw_light(h, table, placed, world_from_local,
                                         cluster_draw_shift(world_from_local.translation));
  Light target = leaf_light(h, h.nodes[drawn]);
  target.position = apply_point(world_from_local, target.position);
  return target;
}

void find_important_lights(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                           float tolerance, const glm::vec3& point, WalkScratch& scratch,
                           std::vector<Light>& important_lights, WalkCounters& counters,
                           glm::vec3* culled_irradiance_bound) {
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  const FittedNodes nodes{volumes.nodes.data()};
  if (culled_irradiance_bound) {
    walk<true, Culled::summed>(hierarchy, nodes, tolerance, point, scratch, important_lights,
                               counters, culled_irradiance_bound);
  } else {
    walk<true, Culled::dropped>(hierarchy, nodes, tolerance, point, scratch, important_lights,
                                counters, nullptr);
  }
}

void find_important_lights_tight_bound(const LightHierarchy& hierarchy,
                                       const ExtentVolumes& volumes, float tolerance,
                                       const glm::vec3& point, WalkScratch& scratch,
                                       std::vector<Light>& important_lights, WalkCounters& counters,
                                       glm::vec3* culled_irradiance_bound) {
  if (!culled_irradiance_bound) {
    find_important_lights(hierarchy, volumes, tolerance, point, scratch, important_lights,
                          counters);
    return;
  }
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  CulledSoFar culled;
  culled.openings_left = kBoundOpeningsPerPoint;
  culled.bound_parts = &scratch.bound_parts;
  if (scratch.radiance) {
    culled.radiance = scratch.radiance;
    culled.radiance_parts = &scratch.radiance_parts;
    scratch.radiance_parts.clear();
  }
  walk<true, Culled::tight>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance, point, scratch,
                            important_lights, counters, culled_irradiance_bound, culled);
}

CulledRadianceBound lev_culled_radiance_bound(const LightHierarchy& hierarchy,
                                              const ExtentVolumes& volumes, float tolerance,
                                              const glm::vec3& point,
                                              const SurfaceResponse& surface, WalkScratch& scratch,
                                              std::vector<Light>& lights) {
  CulledRadianceBound answer;
  answer.surface = surface;
  InspectRecord* const inspect = scratch.inspect;
  scratch.inspect = nullptr;
  scratch.radiance = &answer;
  lights.clear();
  WalkCounters counters;
  glm::vec3 irradiance;
  find_important_lights_tight_bound(hierarchy, volumes, tolerance, point, scratch, lights, counters,
                                    &irradiance);
  scratch.radiance = nullptr;
  scratch.inspect = inspect;
  return answer;
}

glm::dvec3 tightened_irradiance_bound(const LightHierarchy& h, std::uint32_t node,
                                      const FramePoint& x, float refine_above, int& openings_left,
                                      std::vector<BoundPart>& parts) {
  const glm::dvec3 whole(irradiance_bound(h, node, x));
  if (brightest(whole) <= refine_above || openings_left <= 0) return whole;
  glm::dvec3 sum(0.0);
  parts.clear();
  parts.push_back({node, x});
  while (!parts.empty()) {
    BoundPart part = parts.back();
    parts.pop_back();
    const glm::vec3 b = irradiance_bound(h, part.node, part.point);
    // NaN-safe: only a bound known to be small enough is kept whole.
    if (brightest(b) <= refine_above || openings_left <= 0) {
      sum += glm::dvec3(b);
      continue;
    }
    part.node = pass_to_light_or_group(
        h, part.node, [&](const HierarchyNode& n) { enter_transform(h, n, part.point); });
    const HierarchyNode& n = h.nodes[part.node];
    if (node_role(n) == NodeRole::light) {  // its own bound is b
      sum += glm::dvec3(b);
      continue;
    }
    --openings_left;
    for (const std::uint32_t child : group_children(h, n)) parts.push_back({child, part.point});
  }
  // The parts' bounds need not sum below the whole's (each bounds its own cone and box).
  return glm::min(sum, whole);
}

void find_important_and_culled(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                               float tolerance, const glm::vec3& point, WalkScratch& scratch,
                               std::vector<Light>& important_lights, WalkCounters& counters,
                               CulledParts& culled) {
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  culled.clear();
  CulledSoFar so_far;
  so_far.parts = &culled;
  walk<true, Culled::collected>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance, point,
                                scratch, important_lights, counters, nullptr, so_far);
}

void find_lights_within_budget(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                               float tolerance, const glm::vec3& point, WalkScratch& scratch,
                               std::vector<Light>& lights, WalkCounters& counters,
                               glm::vec3* culled_irradiance_bound) {
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  glm::vec3 culled;  // the budget needs the sum either way
  walk<true, Culled::budgeted>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance, point,
                               scratch, lights, counters,
                               culled_irradiance_bound ? culled_irradiance_bound : &culled);
}

void find_lights_and_clusters(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                              float tolerance, const ClusterCut& cut, const glm::vec3& point,
                              WalkScratch& scratch, std::vector<Light>& important_lights,
                              std::vector<Light>& clusters, WalkCounters& counters,
                              glm::vec3* culled_irradiance_bound) {
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  CulledSoFar culled;
  culled.cut = cut;
  culled.clusters = &clusters;
  glm::vec3 bound;  // summed either way: the cut needs each culled part's bound
  walk<true, Culled::clustered>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance, point,
                                scratch, important_lights, counters,
                                culled_irradiance_bound ? culled_irradiance_bound : &bound, culled);
}

namespace {

// The relative cut's state for one walk at this point: what every cut reads, and the lists it
// appends to (WalkScratch's), the culled radiance bound's parts when bound_radiance.
CulledSoFar light_cut_state(const CutNodeTable& table, float relative_error, ShadingPoint& point,
                            WalkScratch& scratch, bool may_refine, bool bound_radiance) {
  CulledSoFar culled;
  culled.cut_nodes = &table;
  culled.scratch = &scratch;
  scratch.representatives.serve(table.first_lights.data(), table.draw_weights.data());
  if (relative_error > 0.0f) {  // at 0 nothing is cut: find_important_lights' walk
    culled.shading = &point;
    culled.estimates = &scratch.cut_estimates;
    culled.surface = point.surface_response();
    culled.relative_error = relative_error;
    culled.point_seed = point_hash(point.position());
    if (may_refine) culled.kept = &scratch.kept_clusters;
  }
  if (bound_radiance) {
    assert(scratch.radiance);
    culled.radiance = scratch.radiance;
    culled.radiance_parts = &scratch.radiance_parts;
  }
  culled.centred = &scratch.centred_clusters;
  scratch.cut_estimates.clear();
  scratch.centred_clusters.clear();
  scratch.exact_clusters.clear();
  scratch.several_light_clusters.clear();
  scratch.kept_clusters.clear();
  return culled;
}

}  // namespace

void start_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                     const CutNodeTable& table, float tolerance, float relative_error,
                     ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                     WalkCounters& counters, bool may_refine, bool bound_radiance,
                     float display_white) {
  assert(volumes.nodes.size() == hierarchy.nodes.size());
  assert(table.draw_weights.size() == hierarchy.nodes.size());
  assert(volumes.tolerance <= tolerance);
  const std::size_t first = lights.size();
  for (float drop_budget = std::numeric_limits<float>::infinity();;) {
    CulledSoFar culled =
        light_cut_state(table, relative_error, point, scratch, may_refine, bound_radiance);
    culled.drop_budget = drop_budget;
    culled.total_floor = kTotalFloorOfWhite * display_white;
    scratch.radiance_parts.clear();
    walk<true, Culled::relative>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance,
                                 point.position(), scratch, lights, counters, nullptr, culled);
    // What the volumes dropped errs as one more cluster would: within the relative error of the
    // cut's total (or of kTotalFloorOfWhite of the display's white, where the total is about 0:
    // bounds are loose where nothing lights the point), or the point is walked again with that as
    // the drop's budget (many lights each below the tolerance, which together light the point).
    const float within = std::max(relative_error * brightest(scratch.cut_sums.total),
                                  relative_error * kTotalFloorOfWhite * display_white);
    if (relative_error == 0.0f || drop_budget != std::numeric_limits<float>::infinity() ||
        !(brightest(scratch.cut_sums.dropped) > within)) {
      // A finer cut going on from this one (refine_light_cut) holds its drop within it too: it
      // opens clusters whose parts the volumes may drop.
      if (drop_budget == std::numeric_limits<float>::infinity()) {
        scratch.cut_sums.drop_budget = within;
      }
      return;
    }
    drop_budget = within;
    lights.resize(first);
    if (scratch.inspect) scratch.inspect->clear_walk();
  }
}

void refine_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                      const CutNodeTable& table, float tolerance, float relative_error,
                      ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                      WalkCounters& counters, bool may_refine) {
  assert(relative_error > 0.0f);
  // The cut before: its lights, estimates and clusters, which the new lists replace.
  scratch.previous_lights.swap(lights);
  scratch.previous_estimates.swap(scratch.cut_estimates);
  scratch.previous_kept.swap(scratch.kept_clusters);
  lights.clear();
  const LightCutSums sums = scratch.cut_sums;
  CulledSoFar culled =
      light_cut_state(table, relative_error, point, scratch, may_refine, sums.radiance);
  culled.total = sums.total;
  culled.sum = sums.culled;
  culled.radiance_sum = sums.radiance_culled;
  culled.radiance_parts_made = sums.radiance_parts_made;
  culled.deferrals = sums.deferrals;
  culled.dropped = sums.dropped;
  culled.drop_budget = sums.drop_budget;
  culled.total_floor = sums.total_floor;
  culled.go_on = true;
  // Its own lights stay; its clusters are put aside again, each with the estimate the total
  // counted for it, in the order they were kept (the heap's ties).
  std::vector<DeferredSubtree>& deferred = scratch.deferred;
  std::vector<DeferredKey>& heap = scratch.deferred_heap;
  deferred.clear();
  heap.clear();
  const std::vector<CutSubtree>& kept = scratch.previous_kept;
  std::size_t next_kept = 0;
  for (std::size_t i = 0; i < scratch.previous_lights.size(); ++i) {
    if (next_kept < kept.size() && kept[next_kept].kept_as == i) {
      const CutSubtree& cluster = kept[next_kept++];
      float bound = brightest(cluster.radiance_bound);
      if (!(bound >= 0.0f)) bound = std::numeric_limits<float>::infinity();
      heap.push_back({bound, culled.deferrals++, static_cast<std::uint32_t>(deferred.size())});
      static_cast<CutSubtree&>(deferred.emplace_back()) = cluster;
      continue;
    }
    lights.push_back(scratch.previous_lights[i]);
    scratch.cut_estimates.push_back(scratch.previous_estimates[i]);
  }
  assert(next_kept == kept.size());
  std::make_heap(heap.begin(), heap.end(), smaller_deferred_bound);
  walk<true, Culled::relative>(hierarchy, FittedNodes{volumes.nodes.data()}, tolerance,
                               point.position(), scratch, lights, counters, nullptr, culled);
}

void answer_light_cut_bounds(const LightHierarchy& hierarchy, float tolerance, WalkScratch& scratch,
                             glm::vec3* culled_irradiance_bound) {
  const LightCutSums& sums = scratch.cut_sums;
  CulledSoFar culled;
  culled.sum = sums.culled;
  if (sums.radiance) {
    culled.radiance = scratch.radiance;
    culled.radiance_parts = &scratch.radiance_parts;
    culled.radiance_sum = sums.radiance_culled;
    culled.radiance_parts_made = sums.radiance_parts_made;
    answer_culled_radiance(hierarchy, tolerance, culled);
    // The clusters' error on top of what the volumes dropped.
    culled.radiance->bound = round_up_sum(glm::dvec3(culled.radiance->bound) + sums.cluster_error);
  }
  if (culled_irradiance_bound) *culled_irradiance_bound = round_up_sum(culled.sum + sums.clusters);
}

void find_light_cut(const LightHierarchy& hierarchy, const ExtentVolumes& volumes,
                    const CutNodeTable& table, float tolerance, float relative_error,
                    ShadingPoint& point, WalkScratch& scratch, std::vector<Light>& lights,
                    WalkCounters& counters, glm::vec3* culled_irradiance_bound,
                    float display_white) {
  start_light_cut(hierarchy, volumes, table, tolerance, relative_error, point, scratch, lights,
                  counters, false, scratch.radiance && culled_irradiance_bound, display_white);
  answer_light_cut_bounds(hierarchy, tolerance, scratch, culled_irradiance_bound);
}

std::vector<Light> flatten_lights(const LightHierarchy& hierarchy) {
  std::vector<Light> lights;
  lights.reserve(hierarchy.light_count);
  WalkScratch scratch;
  WalkCounters counters;
  walk<false, Culled::dropped>(hierarchy, StructureNodes{hierarchy.nodes.data()}, 0.0f,
                               glm::vec3(0.0f), scratch, lights, counters, nullptr);
  return lights;
}

namespace {

void flatten_tree_node(const LightDescription& tree, const LightDescriptionNode& node,
                       const Similarity& world_from_local, std::vector<Light>& out) {
  switch (node_role(node.kind)) {
    case NodeRole::light:
      out.push_back(transform_light(node.light, world_from_local));
      break;
    case NodeRole::transform:
      flatten_tree_node(tree, node.children.at(0), compose(world_from_local, node.transform), out);
      break;
    case NodeRole::bounded:
    case NodeRole::group:
      for (const LightDescriptionNode& child : node.children)
        flatten_tree_node(tree, child, world_from_local, out);
      break;
    case NodeRole::reference:
      flatten_tree_node(tree, tree.masters.at(node.master), world_from_local, out);
      break;
  }
}

}  // namespace

std::vector<Light> flatten_light_description(const LightDescription& tree) {
  std::vector<Light> lights;
  flatten_tree_node(tree, tree.root, Similarity{}, lights);
  return lights;
}

glm::dvec3 culled_radiance_brute_force(const std::vector<Light>& world_lights,
                                       const ShadingPoint& point, float tolerance) {
  glm::dvec3 sum(0.0);
  for (const Light& l : world_lights) {
    if (!is_important(l, point.position(), tolerance))
      sum += glm::dvec3(point.unshadowed_radiance(l));
  }
  return sum;
}

std::vector<Light> important_lights_brute_force(const std::vector<Light>& world_lights,
                                                const glm::vec3& point, float tolerance) {
  std::vector<Light> out;
  for (const Light& l : world_lights) {
    if (is_important(l, point, tolerance)) out.push_back(l);
  }
  return out;
}

}  // namespace lev
