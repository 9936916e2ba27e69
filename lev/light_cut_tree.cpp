#include "lev/light_cut_tree.h"

#include <algorithm>

#include "lev/important_lights.h"
#include "lev/light_selector.h"
#include "lev/light_split.h"

namespace lev {

double node_uniform(std::uint32_t node) {
  // The first number of the stream seeded node * the stream's step: (node + 1) * step hashed.
  RandomStream stream{static_cast<std::uint64_t>(node) * 0x9E3779B97F4A7C15ull};
  return stream.next_double();
}

double draw_weight(const glm::vec3& intensity) {
  return static_cast<double>(intensity.x) + static_cast<double>(intensity.y) +
         static_cast<double>(intensity.z);
}

namespace {

struct Builder {
  const std::vector<Light>& lights;
  std::vector<SplitItem>& items;  // one per light (its id the light's index), partitioned in place
  std::vector<CutTreeNode>& nodes;

  // The node over items[begin, end) (non-empty) at `depth` below the root; returns its index.
  std::uint32_t build(std::size_t begin, std::size_t end, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    if (end - begin == 1) {
      nodes[index].aggregate = light_aggregate(lights[items[begin].id]);
      nodes[index].representative = items[begin].id;
      return index;
    }
    const std::size_t middle = split(begin, end, depth);
    const std::uint32_t left = build(begin, middle, depth + 1);
    const std::uint32_t right = build(middle, end, depth + 1);
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

  // Where items[begin, end) splits: point lights apart from spots first, else where position and
  // orientation together say (light_split.h). Either keeps the flatten order within each part.
  std::size_t split(std::size_t begin, std::size_t end, int depth) {
    const auto first = items.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = items.begin() + static_cast<std::ptrdiff_t>(end);
    const auto is_point = [&](const SplitItem& i) { return lights[i.id].kind == LightKind::point; };
    const auto kinds_end = std::stable_partition(first, last, is_point);
    if (kinds_end != first && kinds_end != last)
      return static_cast<std::size_t>(kinds_end - items.begin());
    return split_items(items, begin, end, depth, SplitAt::cheapest_boundary);
  }
};

}  // namespace

LightCutTree build_light_cut_tree(std::vector<Light> world_lights) {
  LightCutTree tree;
  tree.lights = std::move(world_lights);
  if (tree.lights.empty()) return tree;
  std::vector<SplitItem> items;
  items.reserve(tree.lights.size());
  for (std::size_t i = 0; i < tree.lights.size(); ++i) {
    const Light& light = tree.lights[i];
    items.push_back(split_item({light.position, light.position}, light_aggregate(light),
                               static_cast<std::uint32_t>(i)));
  }
  tree.nodes.reserve(2 * tree.lights.size() - 1);
  Builder{tree.lights, items, tree.nodes}.build(0, items.size(), 0);
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
