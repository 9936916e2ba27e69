// The light hierarchy as queries use it: a flat array of 32-byte nodes addressed by index, built
// once from a LightTree. A node's only child (affine, extent volume, master) sits right after it;
// a union lists its children in `union_children`; an instance names its master's node. Every
// node's children have larger indices than the node, and every master precedes (in
// `master_ranges`) the masters that instance it, so refitting for a new tolerance is one
// backwards sweep per master: each master's volume is computed once, however many instances.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "lev/bounds.h"
#include "lev/light.h"
#include "lev/light_tree.h"
#include "lev/transform.h"

namespace lev {

// HierarchyNode::flags bits.
// An affine node whose transform is a pure translation: the walk composes and inverts it with
// three additions instead of matrix products (the results are the same floats).
inline constexpr std::uint8_t kTranslationOnly = 1;

struct HierarchyNode {
  Bounds volume;               // extent volume of this subtree in this node's frame (refit)
  std::uint32_t payload = 0;   // light | transform | master node | offset into union_children
  NodeKind kind = NodeKind::set_union;
  std::uint8_t flags = 0;      // kTranslationOnly
  std::uint8_t unused[2] = {0, 0};
};
static_assert(sizeof(HierarchyNode) == 32, "hierarchy nodes are 32 bytes");

struct NodeRange {
  std::uint32_t begin = 0;  // the master node (or the root)
  std::uint32_t end = 0;    // one past the last node of its subtree
};

struct LightHierarchy {
  std::vector<HierarchyNode> nodes;
  // For a union at offset k: union_children[k] = child count, then the child node indices.
  std::vector<std::uint32_t> union_children;
  std::vector<Similarity> transforms;
  std::vector<Light> lights;  // in their own frames
  std::vector<NodeRange> master_ranges;  // definition order; the root's range comes last
  std::vector<std::uint64_t> master_light_counts;
  std::uint32_t root = 0;
  std::uint64_t light_count = 0;  // lights in the scene, instances expanded
  float tolerance = 0.0f;         // the tolerance the volumes were last refit for
};

// Deepest LightTree nesting accepted (a guard for scene files, not a limit scenes reach).
inline constexpr int kMaxTreeDepth = 1000;

// Flattens a description. Throws std::invalid_argument for malformed trees (wrong child counts,
// an instance of an undefined or later master, nesting deeper than kMaxTreeDepth, a non-positive
// or non-finite scale). The volumes are computed for `tolerance`.
LightHierarchy build_hierarchy(const LightTree& tree, float tolerance);

// Recomputes every extent volume for a new tolerance without changing the structure.
void refit_hierarchy(LightHierarchy& hierarchy, float tolerance);

// What the structure holds, in bytes: nodes, union child lists, transforms, lights, master table.
std::size_t hierarchy_bytes(const LightHierarchy& hierarchy);

}  // namespace lev
