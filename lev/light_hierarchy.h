// The light hierarchy as queries use it: a flat array of 8-byte nodes addressed by index, built
// once from a LightDescription and never changed after (many renders read one scene's hierarchy at
// once, each at its own tolerance). A node's only child (affine, extent volume, master) sits
// right after it; a union lists its children in `union_children`; an instance names its master's
// node. Every node's children have larger indices than the node, and every master precedes (in
// `master_ranges`) the masters that instance it.
//
// The extent volumes depend on the tolerance, so they live apart from the structure, in an
// ExtentVolumes a render (its `lev` selector) fits for its own tolerance: one backwards sweep per
// master, each master's volume computed once however many instances it has.
//
// The light aggregates (light_bounds.h) do not depend on the tolerance and are part of the
// structure: one per union, one per master and extent volume whose child is neither, shared by a
// master and its instances. A light's is computed from the light; an affine node's is its child's
// seen through the transform, which irradiance_bound applies to the query point instead.
//
// How to step through the nodes, and the bounds read at one, are hierarchy_cursor.h's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lev/bounds.h"
#include "lev/light.h"
#include "lev/light_bounds.h"
#include "lev/light_description.h"
#include "lev/transform.h"

namespace lev {

// HierarchyNode::flags bits.
// An affine node whose transform is a pure translation: the walk composes and inverts it with
// three additions instead of matrix products (the results are the same floats).
inline constexpr std::uint8_t kTranslationOnly = 1;

struct HierarchyNode {
  // light | transform | master node (instance) | offset into union_children | aggregate (extent
  // volume, master)
  std::uint32_t payload = 0;
  NodeKind kind = NodeKind::set_union;
  std::uint8_t flags = 0;  // kTranslationOnly
  std::uint8_t unused[2] = {0, 0};
};
static_assert(sizeof(HierarchyNode) == 8, "hierarchy nodes are 8 bytes");

struct NodeRange {
  std::uint32_t begin = 0;  // the master node (or the root)
  std::uint32_t end = 0;    // one past the last node of its subtree
};

struct LightHierarchy {
  std::vector<HierarchyNode> nodes;
  // For a union at offset k: union_children[k] = child count n, then the n child node indices,
  // then the union's aggregate.
  std::vector<std::uint32_t> union_children;
  std::vector<Similarity> transforms;
  std::vector<Light> lights;               // in their own frames
  std::vector<LightAggregate> aggregates;  // each in the frame of the nodes that refer to it
  std::vector<NodeRange> master_ranges;    // definition order; the root's range comes last
  std::vector<std::uint64_t> master_light_counts;
  std::uint32_t root = 0;
  std::uint64_t light_count = 0;  // lights in the scene, instances expanded
};

// A node with its extent volume, as the culling walk reads it: the volume and the node share one
// 32-byte slot (half a cache line), so testing a child's box and reading its kind is one load.
struct FittedNode {
  Bounds volume;  // extent volume of this subtree in this node's frame
  HierarchyNode node;
};
static_assert(sizeof(FittedNode) == 32, "fitted nodes are 32 bytes");

// The extent volumes of one hierarchy for one tolerance, parallel to LightHierarchy::nodes.
// Valid for a walk at any tolerance >= `tolerance` (a smaller tolerance only grows volumes).
struct ExtentVolumes {
  std::vector<FittedNode> nodes;
  float tolerance = 0.0f;
};

// Deepest LightDescription nesting accepted (a guard for scene files, not a limit scenes reach).
inline constexpr int kMaxTreeDepth = 1000;

// Flattens a description. Throws std::invalid_argument for malformed trees (wrong child counts,
// an instance of an undefined or later master, nesting deeper than kMaxTreeDepth, a non-positive
// or non-finite scale).
LightHierarchy build_hierarchy(const LightDescription& tree);

// Every node's extent volume for `tolerance` (>= 0), the structure unchanged.
ExtentVolumes fit_extent_volumes(const LightHierarchy& hierarchy, float tolerance);

// What the hierarchy needs for a query, in bytes: nodes with one extent volume each (24 bytes,
// the thesis' per-node box), union child lists, transforms, lights, aggregates, master table.
std::size_t hierarchy_bytes(const LightHierarchy& hierarchy);

}  // namespace lev
