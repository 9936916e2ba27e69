// The one place that knows the shape of the light hierarchy. Thesis 4.2.2 names seven node kinds
// (point light, spotlight, affine, extent volume, union, instance, master); a walk only needs to
// know what each does to it, its role: a light ends the walk, a transform moves the frame into its
// child, a bounded node culls its child by its volume, a reference stands for its master's
// subtree, a group has children. node_role is the one switch over the kinds that says what they
// do (node_kind_name, light_description.h, names them); the walks, the aggregate and volume
// builders, the inspector, the samplers and the scene-side conversion step through the hierarchy
// with the functions below and switch on roles, so a new kind that does what one of these does is
// one line in node_role. The functions are inline: the culling walk calls them per node.
//
// Below the cursor sit what a walk reads at a node through it: the aggregate it keeps and the
// irradiance and radiance bounds of its subtree at a point (light_bounds.h).
#pragma once

#include <cstdint>
#include <vector>

#include "lev/light_bounds.h"
#include "lev/light_description.h"
#include "lev/light_hierarchy.h"
#include "lev/transform.h"

namespace lev {

enum class NodeRole : std::uint8_t {
  light,      // point_light, spot_light: a leaf holding one light, in its own frame
  transform,  // affine: one child, the next node, seen through a similarity
  bounded,    // extent_volume, master: one child, the next node, culled by the node's volume
  reference,  // instance: the master's subtree, in the instance's frame
  group,      // set_union: any number of children
};

// No `default:`, so that the compiler names a kind left out.
constexpr NodeRole node_role(NodeKind kind) {
  switch (kind) {
    case NodeKind::point_light:
    case NodeKind::spot_light:
      return NodeRole::light;
    case NodeKind::affine:
      return NodeRole::transform;
    case NodeKind::extent_volume:
    case NodeKind::master:
      return NodeRole::bounded;
    case NodeKind::instance:
      return NodeRole::reference;
    case NodeKind::set_union:
      return NodeRole::group;
  }
  return NodeRole::group;  // not reached: every kind has its case
}

inline NodeRole node_role(const HierarchyNode& n) {
  return node_role(n.kind);
}

// ---- The flat hierarchy (LightHierarchy), as queries walk it.

// The only child of a transform, bounded or reference node at index `node`: the next node, or for
// an instance its master's node.
inline std::uint32_t only_child(const HierarchyNode& n, std::uint32_t node) {
  return node_role(n) == NodeRole::reference ? n.payload : node + 1;
}

// The node below the master a reference refers to: the master's volume is the reference's, so a
// walk that has tested the one steps over the other.
inline std::uint32_t below_referenced_master(const HierarchyNode& reference) {
  return reference.payload + 1;
}

// A group's children, node indices in the hierarchy's order.
struct ChildNodes {
  const std::uint32_t* first = nullptr;
  std::uint32_t count = 0;
  const std::uint32_t* begin() const { return first; }
  const std::uint32_t* end() const { return first + count; }
  std::uint32_t operator[](std::uint32_t k) const { return first[k]; }
};
inline ChildNodes group_children(const LightHierarchy& h, const HierarchyNode& n) {
  const std::uint32_t* list = &h.union_children[n.payload];
  return {list + 1, list[0]};
}

// Where a group keeps the index of its aggregate (kept_aggregate): right after its child list.
inline std::uint32_t group_aggregate_slot(const LightHierarchy& h, const HierarchyNode& n) {
  return n.payload + 1 + h.union_children[n.payload];
}

inline const Light& leaf_light(const LightHierarchy& h, const HierarchyNode& n) {
  return h.lights[n.payload];
}
inline const Similarity& node_transform(const LightHierarchy& h, const HierarchyNode& n) {
  return h.transforms[n.payload];
}
inline bool is_translation_only(const HierarchyNode& n) {
  return (n.flags & kTranslationOnly) != 0;
}
// frame = compose(frame, the transform node's): a pure translation moves the origin alone, as the
// full product would (its rotation is the identity and its scale 1), without the matrix product.
inline void compose_node_transform(const LightHierarchy& h, const HierarchyNode& n,
                                   Similarity& frame) {
  if (is_translation_only(n)) {
    frame.translation = apply_point(frame, node_transform(h, n).translation);
  } else {
    frame = compose(frame, node_transform(h, n));
  }
}

// Moves a point, and any directions given (normals, view directions), from a transform node's
// frame into its child's. A pure translation leaves directions alone and moves the point with
// additions only (the same floats as the full inverse).
template <typename... Directions>
inline void enter_transform(const LightHierarchy& h, const HierarchyNode& n, FramePoint& point,
                            Directions&... directions) {
  const Similarity& xf = node_transform(h, n);
  if (is_translation_only(n)) {
    point = to_translated_frame(point, xf.translation);
    return;
  }
  point = to_node_frame(point, xf);
  if constexpr (sizeof...(Directions) > 0) {
    const glm::mat3 local_from_parent = glm::transpose(xf.rotation);
    ((directions = local_from_parent * directions), ...);
  }
}

// The first node at or below `node` that is not a transform; on_transform(n) is called for each
// transform node passed, top first, so the caller carries whatever frame it needs.
template <typename OnTransform>
inline std::uint32_t pass_transforms(const LightHierarchy& h, std::uint32_t node,
                                     OnTransform&& on_transform) {
  for (; node_role(h.nodes[node]) == NodeRole::transform; ++node) on_transform(h.nodes[node]);
  return node;
}
inline std::uint32_t pass_transforms(const LightHierarchy& h, std::uint32_t node) {
  return pass_transforms(h, node, [](const HierarchyNode&) {});
}

// The first light or group at or below `node`: the nodes with one child (transforms, bounded
// nodes, references) followed down, on_transform(n) called for each transform as above.
template <typename OnTransform>
inline std::uint32_t pass_to_light_or_group(const LightHierarchy& h, std::uint32_t node,
                                            OnTransform&& on_transform) {
  for (;;) {
    const HierarchyNode& n = h.nodes[node];
    switch (node_role(n)) {
      case NodeRole::light:
      case NodeRole::group:
        return node;
      case NodeRole::transform:
        on_transform(n);
        break;
      case NodeRole::bounded:
      case NodeRole::reference:
        break;
    }
    node = only_child(n, node);
  }
}

// A subtree still to be stepped through by for_each_subtree_light: its node and the frame it is
// entered with.
struct SubtreePart {
  std::uint32_t node = 0;
  Similarity world_from_local;
};

// Calls on_light(world_light) for every light of the subtree at `node`, entered with
// world_from_local, in the hierarchy's order (instances expanded; transform_light places each),
// until on_light returns false. `parts` is scratch, so that a caller in a loop allocates once.
template <typename OnLight>
inline void for_each_subtree_light(const LightHierarchy& h, std::uint32_t node,
                                   const Similarity& world_from_local,
                                   std::vector<SubtreePart>& parts, OnLight&& on_light) {
  parts.clear();
  parts.push_back({node, world_from_local});
  while (!parts.empty()) {
    SubtreePart part = parts.back();
    parts.pop_back();
    const std::uint32_t below = pass_to_light_or_group(h, part.node, [&](const HierarchyNode& n) {
      part.world_from_local = compose(part.world_from_local, node_transform(h, n));
    });
    const HierarchyNode& n = h.nodes[below];
    if (node_role(n) == NodeRole::light) {
      if (!on_light(transform_light(leaf_light(h, n), part.world_from_local))) return;
      continue;
    }
    // Last child first on the stack, so the lights come out in the hierarchy's order.
    const ChildNodes children = group_children(h, n);
    for (std::uint32_t k = children.count; k-- > 0;)
      parts.push_back({children[k], part.world_from_local});
  }
}

// The aggregate a bounded, reference or group node keeps (light_bounds.h), in the frame the node
// is entered with: a group's sits after its child list, a reference shares its master's.
inline const LightAggregate& kept_aggregate(const LightHierarchy& h, std::uint32_t node) {
  const HierarchyNode& n = h.nodes[node];
  const NodeRole role = node_role(n);
  if (role == NodeRole::group) {
    return h.aggregates[h.union_children[group_aggregate_slot(h, n)]];
  }
  if (role == NodeRole::reference) return h.aggregates[h.nodes[n.payload].payload];
  return h.aggregates[n.payload];
}
// The same for any node: null for a transform, whose subtree is seen through it, and for a light,
// which has none stored.
inline const LightAggregate* stored_aggregate(const LightHierarchy& h, std::uint32_t node) {
  const NodeRole role = node_role(h.nodes[node]);
  if (role == NodeRole::transform || role == NodeRole::light) return nullptr;
  return &kept_aggregate(h, node);
}

// Upper bound of the summed unshadowed irradiance (RGB) of the node's lights at x, given in the
// frame the node is entered with (light_bounds.h). Transforms move x into their child's frame.
inline glm::vec3 irradiance_bound(const LightHierarchy& h, std::uint32_t node,
                                  const FramePoint& x) {
  FramePoint local = x;
  node = pass_transforms(h, node, [&](const HierarchyNode& n) { enter_transform(h, n, local); });
  const HierarchyNode& n = h.nodes[node];
  if (node_role(n) == NodeRole::light) {
    return irradiance_bound(light_aggregate(leaf_light(h, n)), local);
  }
  return irradiance_bound(kept_aggregate(h, node), local);
}

// The surface as seen from a frame whose world_from_local rotation is `rotation`: its directions
// turned into the frame. The response depends on directions alone, so a scale changes nothing.
inline SurfaceResponse surface_in_frame(const SurfaceResponse& surface, const glm::mat3& rotation) {
  SurfaceResponse local = surface;
  const glm::mat3 local_from_world = glm::transpose(rotation);
  local.normal = local_from_world * surface.normal;
  local.mirrored_view = local_from_world * surface.mirrored_view;
  return local;
}

// light_bounds.h's radiance_bound of the node's lights at x: the cluster bound, visibility 1,
// with x and the surface given in the frame the node is entered with (transforms move both
// into their child's frame, as irradiance_bound moves x). When `irradiance` is given it receives
// the irradiance part, irradiance_bound's.
inline glm::vec3 radiance_bound(const LightHierarchy& h, std::uint32_t node, const FramePoint& x,
                                const SurfaceResponse& surface, glm::vec3* irradiance = nullptr) {
  FramePoint local = x;
  SurfaceResponse local_surface = surface;
  node = pass_transforms(h, node, [&](const HierarchyNode& n) {
    enter_transform(h, n, local, local_surface.normal, local_surface.mirrored_view);
  });
  const HierarchyNode& n = h.nodes[node];
  if (node_role(n) == NodeRole::light) {
    return radiance_bound(light_aggregate(leaf_light(h, n)), local, local_surface, irradiance);
  }
  return radiance_bound(kept_aggregate(h, node), local, local_surface, irradiance);
}

}  // namespace lev
