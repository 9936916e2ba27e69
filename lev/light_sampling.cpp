#include "lev/light_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lev/hierarchy_cursor.h"
#include "lev/light_bounds.h"

namespace lev {
namespace {

// The share of its bound a light keeps where its exact importance is zero (the point just
// outside its cone or behind the surface plane, as far as rounding can tell): small enough not
// to waste samples, never zero where the bound is not.
constexpr double kEdgeShare = 1e-3;
// The cosine factor never drops below this where the box may still lie in front of the surface.
constexpr float kMinCosine = 1e-3f;
// Where the ball around a box subtends less than this sine (beyond 4 radii), its bound of the
// cosine is sharp enough and the projection's is skipped.
constexpr float kSphereIsSharp = 0.25f;
// Squared distances below this are clamped, as irradiance clamps at kMinLightDistance.
constexpr double kMinDistance2 = 1e-36;

double channel_sum(const glm::vec3& v) {
  return static_cast<double>(v.x) + static_cast<double>(v.y) + static_cast<double>(v.z);
}

// An aggregate's summed intensity is rounded up in float, so lights summing past the largest
// float (a few lights of the largest float; 400 lights of 1e12 under a scene file's scales of
// 1e12) make it +inf. Its importance takes it as three largest floats instead: an infinite weight
// made a part's or a child's probability weight / total inf / inf, NaN, and the pixels of
// light_tree and lev_mc NaN. Still the largest weight a part can have.
double finite_intensity(const glm::vec3& intensity) {
  constexpr double kLargest = 3.0 * static_cast<double>(std::numeric_limits<float>::max());
  return std::min(channel_sum(intensity), kLargest);
}

// The largest cos(theta) between the normal and a direction from x into a ball of squared
// radius r2 around `to_centre` (x at the origin), at least kMinCosine; 0 when the box with half
// extent `half` lies behind the surface plane by more than rounding can explain.
float cosine_factor(const glm::vec3& normal, const glm::vec3& to_centre, const glm::vec3& half,
                    float r2, float rounding) {
  if (normal == glm::vec3(0.0f)) return 1.0f;
  const float slack = rounding + kFrameRounding * (max_abs(to_centre) + max_abs(half));
  if (glm::dot(normal, to_centre) + glm::dot(glm::abs(normal), half) < -slack) return 0.0f;
  const float d2 = glm::dot(to_centre, to_centre);
  if (d2 <= r2) return 1.0f;
  const float d = std::sqrt(d2);
  const float sin_b = std::sqrt(r2) / d;
  const float cos_b = std::sqrt(std::max(0.0f, (1.0f - sin_b) * (1.0f + sin_b)));
  const float cos_n = glm::dot(normal, to_centre) / d;
  if (cos_n >= cos_b) return 1.0f;
  const float sin_n = glm::length(glm::cross(normal, to_centre)) / d;
  const float by_sphere = cos_n * cos_b + sin_n * sin_b;
  // The sphere's bound and, near the box, the projection's (light_bounds.h), the smaller: the
  // projection is the sharper one for a flat box seen edge-on from close by.
  if (sin_b < kSphereIsSharp) return std::max(kMinCosine, by_sphere);
  const float by_projection = cos_angle_bound_by_projection(-normal, -to_centre, half);
  return std::max(kMinCosine, std::min(by_sphere, by_projection));
}

// pbrt-v4's importance of an aggregate (header comment), zero exactly where irradiance_bound is
// or the box is behind the surface.
double aggregate_importance(const LightAggregate& a, const FramePoint& x, const glm::vec3& normal) {
  if (is_empty(a)) return 0.0;
  const double intensity = finite_intensity(a.intensity);
  if (!(intensity > 0.0)) return 0.0;
  const float cone = shines_everywhere(a) ? 1.0f : spot_cone_factor(a, x);
  if (cone == 0.0f) return 0.0;
  const glm::vec3 half = 0.5f * (a.positions.hi - a.positions.lo);
  const glm::vec3 to_centre = 0.5f * (a.positions.lo + a.positions.hi) - x.point;
  const float r2 = glm::dot(half, half);
  const float cosine = cosine_factor(normal, to_centre, half, r2, x.rounding);
  if (cosine == 0.0f) return 0.0;
  const double d2 = std::max({static_cast<double>(glm::dot(to_centre, to_centre)),
                              static_cast<double>(r2), kMinDistance2});
  return intensity * static_cast<double>(cone) * static_cast<double>(cosine) / d2;
}

// Where a descent stands: the node's frame (world_from_local), the point and normal in it.
struct DescentFrame {
  Similarity world_from_local;
  FramePoint point;
  glm::vec3 normal{0.0f};
};

// Follows the nodes that do not branch (transforms, bounded nodes, references) down to the next
// light or union, the frame moved along.
void pass_through(const LightHierarchy& h, std::uint32_t& node, DescentFrame& frame) {
  node = pass_to_light_or_group(h, node, [&](const HierarchyNode& n) {
    frame.world_from_local = compose(frame.world_from_local, node_transform(h, n));
    enter_transform(h, n, frame.point, frame.normal);
  });
}

double light_draw_weight(const Light& light, const FramePoint& x, const glm::vec3& normal,
                         bool& edge) {
  edge = false;
  double e = channel_sum(irradiance(light, x.point));
  if (e > 0.0 && normal != glm::vec3(0.0f)) {
    const glm::vec3 to_light = light.position - x.point;
    const float d = glm::length(to_light);
    const float cosine = d > 0.0f ? glm::dot(normal, to_light) / d : 1.0f;
    e *= std::max(0.0f, cosine);
  }
  if (e > 0.0) return e;
  edge = true;
  return kEdgeShare * aggregate_importance(light_aggregate(light), x, normal);
}

double subtree_draw_weight(const LightHierarchy& h, std::uint32_t node, const FramePoint& local,
                           const glm::vec3& local_normal, bool& edge) {
  edge = false;
  // Point and normal only, as pass_through moves them: the importance needs no world_from_local.
  FramePoint point = local;
  glm::vec3 normal = local_normal;
  node = pass_transforms(h, node,
                         [&](const HierarchyNode& n) { enter_transform(h, n, point, normal); });
  const HierarchyNode& n = h.nodes[node];
  if (node_role(n) == NodeRole::light)
    return light_draw_weight(leaf_light(h, n), point, normal, edge);
  return aggregate_importance(kept_aggregate(h, node), point, normal);
}

// Weights of a set to draw from, where a light whose exact importance is zero (edge) keeps at most
// kEdgeShare of what the others weigh together: its edge share is of a bound that grows as
// 1 / d^2 near it, so a spot of 400 a millimetre behind the point (dark there) weighed 500,000,
// and the light of 14 that gave the point all its light was drawn once in 800,000 draws
// (light_tree's passes never settled; a firefly of 800,000 times the pixel when it was drawn). Edge
// weights are pushed negative and made positive by `finish`.
struct EdgeLimitedWeights {
  std::vector<double>& weights;
  double total = 0.0;
  double edge_total = 0.0;

  void push(double w, bool edge) {
    if (edge) {
      weights.push_back(-w);
      edge_total += w;
    } else {
      weights.push_back(w);
      total += w;
    }
  }
  // The weights made positive; returns their sum.
  double finish() {
    const double limit = kEdgeShare * total;
    const double scale = total > 0.0 && edge_total > limit ? limit / edge_total : 1.0;
    double sum = 0.0;
    for (double& w : weights) {
      if (std::signbit(w)) {
        const double edge = -w;
        w = edge * scale;
        // Never zero where the edge share was not: such a light stays drawable.
        if (edge > 0.0 && !(w > 0.0)) w = std::numeric_limits<double>::denorm_min();
      }
      sum += w;
    }
    return sum;
  }
};

// The importances of a union's children into weights; returns their sum. When every child's is
// zero (the union's own aggregate is looser than its children's) they are weighed alike, so a
// descent always ends at a light and its probabilities sum to 1; such lights cannot light the
// point and cost no shadow ray.
double child_weights(const LightHierarchy& h, std::uint32_t union_node, const DescentFrame& frame,
                     std::vector<double>& weights, std::uint64_t& nodes_visited) {
  const ChildNodes children = group_children(h, h.nodes[union_node]);
  const std::uint32_t count = children.count;
  weights.clear();
  EdgeLimitedWeights limited{weights};
  for (const std::uint32_t child : children) {
    bool edge = false;
    const double w = subtree_draw_weight(h, child, frame.point, frame.normal, edge);
    limited.push(w, edge);
  }
  const double total = limited.finish();
  nodes_visited += count;
  if (total > 0.0) return total;
  weights.assign(count, 1.0);
  return static_cast<double>(count);
}

DescentFrame start_frame(const SubtreeRef& start, const SamplingPoint& point) {
  return {start.world_from_local, start.point,
          glm::transpose(start.world_from_local.rotation) * point.normal};
}

void enumerate(const LightHierarchy& h, std::uint32_t node, DescentFrame frame, double probability,
               std::vector<SampledLight>& out) {
  pass_through(h, node, frame);
  const HierarchyNode& n = h.nodes[node];
  if (node_role(n) == NodeRole::light) {
    out.push_back({transform_light(leaf_light(h, n), frame.world_from_local), probability});
    return;
  }
  std::vector<double> weights;
  std::uint64_t visited = 0;
  const double total = child_weights(h, node, frame, weights, visited);
  const ChildNodes children = group_children(h, n);
  for (std::uint32_t k = 0; k < weights.size(); ++k) {
    const double p = probability * (weights[k] / total);
    enumerate(h, children[k], frame, p, out);
  }
}

}  // namespace

SubtreeRef whole_hierarchy(const LightHierarchy& hierarchy, const glm::vec3& world_point) {
  return {hierarchy.root, Similarity{}, world_frame_point(world_point)};
}

double light_importance(const Light& light, const FramePoint& x, const glm::vec3& normal) {
  bool edge = false;
  return light_draw_weight(light, x, normal, edge);
}

double subtree_importance(const LightHierarchy& h, std::uint32_t node, const FramePoint& local,
                          const glm::vec3& local_normal) {
  bool edge = false;
  return subtree_draw_weight(h, node, local, local_normal, edge);
}

std::size_t choose_weighted(const std::vector<double>& weights, double total, float u) {
  const double target = static_cast<double>(u) * total;
  double cumulative = 0.0;
  std::size_t last = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0.0)) continue;
    last = i;
    cumulative += weights[i];
    if (target < cumulative) return i;
  }
  return last;  // u * total rounded up to the sum
}

void sample_light(const LightHierarchy& h, const SubtreeRef& start, const SamplingPoint& point,
                  RandomStream& random, std::vector<double>& weights, SampledLight& sampled,
                  std::uint64_t& nodes_visited) {
  std::uint32_t node = start.node;
  DescentFrame frame = start_frame(start, point);
  double probability = 1.0;
  for (;;) {
    pass_through(h, node, frame);
    const HierarchyNode& n = h.nodes[node];
    if (node_role(n) == NodeRole::light) {
      sampled.light = transform_light(leaf_light(h, n), frame.world_from_local);
      sampled.probability = probability;
      return;
    }
    const double total = child_weights(h, node, frame, weights, nodes_visited);
    const std::size_t k = choose_weighted(weights, total, random.next_float());
    probability *= weights[k] / total;
    node = group_children(h, n)[static_cast<std::uint32_t>(k)];
  }
}

void light_probabilities(const LightHierarchy& hierarchy, const SubtreeRef& start,
                         const SamplingPoint& point, std::vector<SampledLight>& lights) {
  lights.clear();
  enumerate(hierarchy, start.node, start_frame(start, point), 1.0, lights);
}

void open_wide_parts(const LightHierarchy& h, CulledParts& parts, std::size_t max_parts,
                     std::vector<SubtreeRef>& queue) {
  static const float cos_wide = std::cos(kWideAxisSpread);
  queue.clear();
  queue.swap(parts.subtrees);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    std::uint32_t node = queue[head].node;
    DescentFrame frame{queue[head].world_from_local, queue[head].point, glm::vec3(0.0f)};
    pass_through(h, node, frame);
    const HierarchyNode& n = h.nodes[node];
    bool open = false;
    if (node_role(n) == NodeRole::group) {
      const LightAggregate& a = kept_aggregate(h, node);
      // The parts if this one opened: those kept, those still queued, the lights, its children.
      const std::size_t parts_after = parts.subtrees.size() + (queue.size() - head - 1) +
                                      parts.lights.size() + group_children(h, n).count;
      open = !shines_everywhere(a) && a.cos_axis_spread < cos_wide && parts_after <= max_parts;
    }
    if (!open) {
      parts.subtrees.push_back(queue[head]);
      continue;
    }
    for (const std::uint32_t child : group_children(h, n))
      queue.push_back({child, frame.world_from_local, frame.point});
  }
}

glm::vec3 sampled_radiance(const LightHierarchy& hierarchy, int k, ShadingPoint& point,
                           RandomStream& random, SamplingScratch& scratch,
                           SelectionCounters& counters, glm::dvec3* draw_square_sum,
                           InspectRecord* record) {
  open_wide_parts(hierarchy, scratch.parts, sampled_parts_budget(k), scratch.queue);
  const CulledParts& parts = scratch.parts;
  std::vector<double>& part_weights = scratch.part_weights;
  std::vector<double>& weights = scratch.weights;
  const SamplingPoint at{point.position(), point.normal()};
  const FramePoint world_point = world_frame_point(at.position);
  part_weights.clear();
  EdgeLimitedWeights limited{part_weights};
  for (const SubtreeRef& subtree : parts.subtrees) {
    bool edge = false;
    const double w =
        subtree_draw_weight(hierarchy, subtree.node, subtree.point,
                            glm::transpose(subtree.world_from_local.rotation) * at.normal, edge);
    limited.push(w, edge);
  }
  for (const Light& light : parts.lights) {
    bool edge = false;
    const double w = light_draw_weight(light, world_point, at.normal, edge);
    limited.push(w, edge);
  }
  const double total = limited.finish();
  counters.nodes_visited += part_weights.size();
  scratch.nothing_to_draw = !(total > 0.0);
  if (scratch.nothing_to_draw) return glm::vec3(0.0f);
  glm::dvec3 sum(0.0);
  SampledLight sampled;
  for (int draw = 0; draw < k; ++draw) {
    const std::size_t part = choose_weighted(part_weights, total, random.next_float());
    const double part_probability = part_weights[part] / total;
    if (part < parts.subtrees.size()) {
      sample_light(hierarchy, parts.subtrees[part], at, random, weights, sampled,
                   counters.nodes_visited);
    } else {
      sampled.light = parts.lights[part - parts.subtrees.size()];
      sampled.probability = 1.0;
    }
    ++counters.lights_tested;
    const glm::vec3 radiance = point.unshadowed_radiance(sampled.light);
    ShadedLight* shaded = nullptr;
    if (record) {
      shaded = &record->shaded.emplace_back();
      shaded->light = sampled.light;
      shaded->role = InspectRole::sampled;
      shaded->unshadowed_radiance = radiance;
      shaded->weight = 1.0 / (part_probability * sampled.probability * static_cast<double>(k));
    }
    if (radiance == glm::vec3(0.0f)) continue;
    ++counters.shadow_rays;
    const bool visible = point.visible(sampled.light);
    if (shaded) {
      shaded->shadow_ray = true;
      shaded->visible = visible;
      if (visible) shaded->contribution = glm::vec3(glm::dvec3(radiance) * shaded->weight);
    }
    if (!visible) continue;
    const glm::dvec3 weighed = glm::dvec3(radiance) / (part_probability * sampled.probability);
    sum += weighed;
    if (draw_square_sum) *draw_square_sum += weighed * weighed;
  }
  return glm::vec3(
      glm::min(sum / static_cast<double>(k), glm::dvec3(std::numeric_limits<float>::max())));
}

}  // namespace lev
