#include "lev/light_bvh.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "lev/hierarchy_cursor.h"

namespace lev {
namespace {

constexpr std::size_t kLeafSize = 4;

using Iter = std::vector<std::uint32_t>::iterator;

// Splits [begin, end) at its median along the widest axis of the item centres.
Iter split_at_median(const std::vector<glm::vec3>& centres, Iter begin, Iter end) {
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (Iter it = begin; it != end; ++it) {
    lo = glm::min(lo, centres[*it]);
    hi = glm::max(hi, centres[*it]);
  }
  const glm::vec3 extent = hi - lo;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  Iter mid = begin + (end - begin) / 2;
  std::nth_element(begin, mid, end, [&](std::uint32_t a, std::uint32_t b) {
    const float pa = centres[a][axis], pb = centres[b][axis];
    return pa < pb || (pa == pb && a < b);
  });
  return mid;
}

LightDescriptionNode build(std::vector<BvhItem>& items, const std::vector<glm::vec3>& centres,
                           Iter begin, Iter end) {
  const auto count = static_cast<std::size_t>(end - begin);
  if (count == 1) return std::move(items[*begin].node);
  std::vector<LightDescriptionNode> children;
  if (count <= kLeafSize) {
    // Keep the input order inside a leaf so a sorted list stays sorted.
    std::vector<std::uint32_t> leaf(begin, end);
    std::sort(leaf.begin(), leaf.end());
    for (std::uint32_t i : leaf) children.push_back(std::move(items[i].node));
  } else {
    const Iter mid = split_at_median(centres, begin, end);
    const Iter left_mid = split_at_median(centres, begin, mid);
    const Iter right_mid = split_at_median(centres, mid, end);
    for (auto [b, e] : {std::pair{begin, left_mid}, std::pair{left_mid, mid},
                        std::pair{mid, right_mid}, std::pair{right_mid, end}}) {
      if (b != e) children.push_back(build(items, centres, b, e));
    }
  }
  return extent_volume_node(union_node(std::move(children)));
}

}  // namespace

LightDescriptionNode build_bvh(std::vector<BvhItem> items) {
  if (items.empty()) return union_node({});
  // The centre of a light's box is its position, exactly (p + p and the halving are exact).
  std::vector<glm::vec3> centres;
  centres.reserve(items.size());
  for (const BvhItem& item : items)
    centres.push_back(0.5f * (item.light_positions.lo + item.light_positions.hi));
  std::vector<std::uint32_t> order(items.size());
  std::iota(order.begin(), order.end(), 0u);
  return build(items, centres, order.begin(), order.end());
}

LightDescriptionNode build_light_bvh(const std::vector<Light>& lights) {
  std::vector<BvhItem> items;
  items.reserve(lights.size());
  for (const Light& l : lights) items.push_back({light_node(l), Bounds{l.position, l.position}});
  return build_bvh(std::move(items));
}

Bounds light_positions(const LightDescriptionNode& node,
                       const std::vector<Bounds>& master_light_positions) {
  switch (node_role(node.kind)) {
    case NodeRole::light:
      return {node.light.position, node.light.position};
    case NodeRole::transform:
      return transform_bounds(light_positions(node.children.at(0), master_light_positions),
                              node.transform);
    case NodeRole::reference:
      return master_light_positions.at(node.master);
    case NodeRole::bounded:
    case NodeRole::group:
      break;
  }
  Bounds b;
  for (const LightDescriptionNode& child : node.children)
    b = merge(b, light_positions(child, master_light_positions));
  return b;
}

}  // namespace lev
