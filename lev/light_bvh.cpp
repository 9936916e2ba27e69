#include "lev/light_bvh.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "lev/hierarchy_cursor.h"
#include "lev/light_split.h"

namespace lev {
namespace {

constexpr std::size_t kLeafSize = 4;

// The node over split[begin, end) (non-empty; an item's id is its index in `items`), `depth`
// binary splits below the root.
LightDescriptionNode build(std::vector<BvhItem>& items, std::vector<SplitItem>& split,
                           std::size_t begin, std::size_t end, int depth) {
  const std::size_t count = end - begin;
  if (count == 1) return std::move(items[split[begin].id].node);
  std::vector<LightDescriptionNode> children;
  if (count <= kLeafSize) {
    // Keep the input order inside a leaf so a sorted list stays sorted.
    std::vector<std::uint32_t> leaf;
    for (std::size_t i = begin; i < end; ++i) leaf.push_back(split[i].id);
    std::sort(leaf.begin(), leaf.end());
    for (std::uint32_t i : leaf) children.push_back(std::move(items[i].node));
  } else {
    // Two binary splits make the four children (three when a first part is a single item: only
    // the median of two or three makes one).
    const std::size_t mid = split_items(split, begin, end, depth, SplitAt::median);
    for (auto [b, e] : {std::pair{begin, mid}, std::pair{mid, end}}) {
      if (e - b == 1) {
        children.push_back(build(items, split, b, e, depth + 1));
        continue;
      }
      const std::size_t quarter = split_items(split, b, e, depth + 1, SplitAt::median);
      children.push_back(build(items, split, b, quarter, depth + 2));
      children.push_back(build(items, split, quarter, e, depth + 2));
    }
  }
  return extent_volume_node(union_node(std::move(children)));
}

}  // namespace

LightDescriptionNode build_bvh(std::vector<BvhItem> items) {
  if (items.empty()) return union_node({});
  std::vector<SplitItem> split;
  split.reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i)
    split.push_back(split_item(items[i].lights.positions, items[i].lights.aggregate,
                               static_cast<std::uint32_t>(i)));
  return build(items, split, 0, split.size(), 0);
}

LightDescriptionNode build_light_bvh(const std::vector<Light>& lights) {
  std::vector<BvhItem> items;
  items.reserve(lights.size());
  for (const Light& l : lights)
    items.push_back({light_node(l), {{l.position, l.position}, light_aggregate(l)}});
  return build_bvh(std::move(items));
}

SubtreeLights subtree_lights(const LightDescriptionNode& node,
                             const std::vector<SubtreeLights>& master_lights) {
  switch (node_role(node.kind)) {
    case NodeRole::light:
      return {{node.light.position, node.light.position}, light_aggregate(node.light)};
    case NodeRole::transform: {
      const SubtreeLights child = subtree_lights(node.children.at(0), master_lights);
      return {transform_bounds(child.positions, node.transform),
              transform_aggregate(child.aggregate, node.transform)};
    }
    case NodeRole::reference:
      return master_lights.at(node.master);
    case NodeRole::bounded:
    case NodeRole::group:
      break;
  }
  SubtreeLights all;
  for (const LightDescriptionNode& child : node.children) {
    const SubtreeLights c = subtree_lights(child, master_lights);
    all.positions = merge(all.positions, c.positions);
    all.aggregate = merge_aggregates(all.aggregate, c.aggregate);
  }
  return all;
}

}  // namespace lev
