#include "lev/light_cut_tree.h"

#include <algorithm>
#include <numeric>

#include "lev/important_lights.h"

namespace lev {

double node_uniform(std::uint32_t node) {
  std::uint64_t z = (static_cast<std::uint64_t>(node) + 1) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double draw_weight(const glm::vec3& intensity) {
  return static_cast<double>(intensity.x) + static_cast<double>(intensity.y) +
         static_cast<double>(intensity.z);
}

namespace {

struct Builder {
  const std::vector<Light>& lights;
  std::vector<CutTreeNode>& nodes;
  std::vector<std::uint32_t>& order;  // light indices, partitioned in place

  // The node over order[begin, end) (non-empty); returns its index.
  std::uint32_t build(std::size_t begin, std::size_t end) {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    if (end - begin == 1) {
      nodes[index].aggregate = light_aggregate(lights[order[begin]]);
      nodes[index].representative = order[begin];
      return index;
    }
    const std::size_t middle = split(begin, end);
    const std::uint32_t left = build(begin, middle);
    const std::uint32_t right = build(middle, end);
    CutTreeNode& node = nodes[index];
    node.children[0] = left;
    node.children[1] = right;
    node.aggregate = merge_aggregates(nodes[left].aggregate, nodes[right].aggregate);
    const double w_left = draw_weight(nodes[left].aggregate.intensity);
    const double w_right = draw_weight(nodes[right].aggregate.intensity);
    const double total = w_left + w_right;
    // Without weight (dark lights) the left child's stands for both.
    const bool take_left = !(total > 0.0) || node_uniform(index) * total < w_left;
    node.representative = nodes[take_left ? left : right].representative;
    return index;
  }

  // Where order[begin, end) splits: point lights apart from spots first, else at the median of
  // the longest axis of the positions' box. Ties keep the flatten order, so the tree is the same
  // on every platform.
  std::size_t split(std::size_t begin, std::size_t end) {
    const auto first = order.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = order.begin() + static_cast<std::ptrdiff_t>(end);
    const auto is_point = [&](std::uint32_t i) { return lights[i].kind == LightKind::point; };
    const auto kinds_end = std::stable_partition(first, last, is_point);
    if (kinds_end != first && kinds_end != last)
      return static_cast<std::size_t>(kinds_end - order.begin());
    Bounds box;
    for (auto it = first; it != last; ++it)
      box = merge(box, {lights[*it].position, lights[*it].position});
    const glm::vec3 extent = box.hi - box.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto middle = first + (last - first) / 2;
    std::nth_element(first, middle, last, [&](std::uint32_t a, std::uint32_t b) {
      const float pa = lights[a].position[axis], pb = lights[b].position[axis];
      return pa < pb || (pa == pb && a < b);
    });
    return static_cast<std::size_t>(middle - order.begin());
  }
};

}  // namespace

LightCutTree build_light_cut_tree(std::vector<Light> world_lights) {
  LightCutTree tree;
  tree.lights = std::move(world_lights);
  if (tree.lights.empty()) return tree;
  std::vector<std::uint32_t> order(tree.lights.size());
  std::iota(order.begin(), order.end(), 0u);
  tree.nodes.reserve(2 * tree.lights.size() - 1);
  Builder{tree.lights, tree.nodes, order}.build(0, order.size());
  return tree;
}

LightCutTree build_light_cut_tree(const LightHierarchy& hierarchy) {
  return build_light_cut_tree(flatten_lights(hierarchy));
}

Light cluster_light(const LightCutTree& tree, std::uint32_t node) {
  const CutTreeNode& n = tree.nodes[node];
  Light light = tree.lights[n.representative];
  if (!n.is_leaf()) light.intensity = n.aggregate.intensity;
  return light;
}

}  // namespace lev
