#include "lev/light_hierarchy.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "lev/extent_volume.h"
#include "lev/hierarchy_cursor.h"

namespace lev {
namespace {

// Rounding in the walk (the query point travels through inverse transforms) must never cull a
// light whose world-space irradiance passes; every volume is grown by this relative margin.
constexpr float kVolumePadding = 1e-5f;

class Flattener {
 public:
  explicit Flattener(LightHierarchy& h) : h_(h) {}

  std::uint32_t add(const LightDescriptionNode& src, int depth, std::uint32_t current_master) {
    if (depth > kMaxTreeDepth) {
      throw std::invalid_argument("light description nested deeper than " +
                                  std::to_string(kMaxTreeDepth));
    }
    const auto index = static_cast<std::uint32_t>(h_.nodes.size());
    h_.nodes.push_back({});
    h_.nodes[index].kind = src.kind;
    auto expect_children = [&](std::size_t n) {
      if (src.children.size() != n) {
        throw std::invalid_argument(std::string(node_kind_name(src.kind)) + " node needs " +
                                    std::to_string(n) + " child(ren), has " +
                                    std::to_string(src.children.size()));
      }
    };
    switch (node_role(src.kind)) {
      case NodeRole::light: {
        expect_children(0);
        const bool spot = src.light.kind == LightKind::spot;
        if (spot != (src.kind == NodeKind::spot_light)) {
          throw std::invalid_argument("light node kind does not match its light");
        }
        h_.nodes[index].payload = static_cast<std::uint32_t>(h_.lights.size());
        h_.lights.push_back(src.light);
        light_count_ += 1;
        break;
      }
      case NodeRole::transform: {
        expect_children(1);
        const Similarity& xf = src.transform;
        if (!(xf.scale > 0.0f) || !std::isfinite(xf.scale)) {
          throw std::invalid_argument("affine scale must be finite and > 0, got " +
                                      std::to_string(xf.scale));
        }
        h_.nodes[index].payload = static_cast<std::uint32_t>(h_.transforms.size());
        if (xf.rotation == glm::mat3(1.0f) && xf.scale == 1.0f)
          h_.nodes[index].flags |= kTranslationOnly;
        h_.transforms.push_back(xf);
        add(src.children[0], depth + 1, current_master);
        break;
      }
      case NodeRole::bounded:
        if (src.kind == NodeKind::master) {
          throw std::invalid_argument(
              "master nodes are declared in LightDescription::masters only");
        }
        expect_children(1);
        add(src.children[0], depth + 1, current_master);
        break;
      case NodeRole::group: {
        const auto offset = static_cast<std::uint32_t>(h_.union_children.size());
        h_.nodes[index].payload = offset;
        h_.union_children.push_back(static_cast<std::uint32_t>(src.children.size()));
        // The children, then a slot for the union's aggregate (attach_aggregates).
        h_.union_children.resize(h_.union_children.size() + src.children.size() + 1);
        for (std::size_t k = 0; k < src.children.size(); ++k) {
          const std::uint32_t child = add(src.children[k], depth + 1, current_master);
          h_.union_children[offset + 1 + k] = child;
        }
        break;
      }
      case NodeRole::reference:
        expect_children(0);
        if (src.master >= current_master) {
          throw std::invalid_argument("instance of master " + std::to_string(src.master) +
                                      " which is not defined before its use");
        }
        h_.nodes[index].payload = h_.master_ranges[src.master].begin;
        light_count_ += h_.master_light_counts[src.master];
        break;
    }
    return index;
  }

  std::uint64_t take_light_count() {
    const std::uint64_t n = light_count_;
    light_count_ = 0;
    return n;
  }

 private:
  LightHierarchy& h_;
  std::uint64_t light_count_ = 0;
};

constexpr std::uint32_t kNoAggregate = ~0u;

// One backwards sweep per master, like fit_extent_volumes: every node's aggregate in the frame it
// is entered with, of which unions, masters and extent volumes keep theirs (a master or extent
// volume shares its child's when that child keeps one, an instance its master's).
void attach_aggregates(LightHierarchy& h) {
  std::vector<LightAggregate> of_node(h.nodes.size());
  std::vector<std::uint32_t> kept(h.nodes.size(), kNoAggregate);
  const auto keep = [&h](const LightAggregate& a) {
    h.aggregates.push_back(a);
    return static_cast<std::uint32_t>(h.aggregates.size() - 1);
  };
  for (const NodeRange& range : h.master_ranges) {
    for (std::uint32_t i = range.end; i-- > range.begin;) {
      HierarchyNode& node = h.nodes[i];
      switch (node_role(node)) {
        case NodeRole::light:
          of_node[i] = light_aggregate(leaf_light(h, node));
          break;
        case NodeRole::transform:
          of_node[i] = transform_aggregate(of_node[only_child(node, i)], node_transform(h, node));
          break;
        case NodeRole::bounded: {
          const std::uint32_t child = only_child(node, i);
          of_node[i] = of_node[child];
          kept[i] = kept[child] != kNoAggregate ? kept[child] : keep(of_node[i]);
          node.payload = kept[i];
          break;
        }
        case NodeRole::group: {
          LightAggregate a;
          for (const std::uint32_t child : group_children(h, node))
            a = merge_aggregates(a, of_node[child]);
          of_node[i] = a;
          kept[i] = keep(a);
          h.union_children[group_aggregate_slot(h, node)] = kept[i];
          break;
        }
        case NodeRole::reference:
          of_node[i] = of_node[only_child(node, i)];
          kept[i] = kept[only_child(node, i)];
          break;
      }
    }
  }
}

}  // namespace

LightHierarchy build_hierarchy(const LightDescription& tree) {
  LightHierarchy h;
  Flattener flattener(h);
  for (std::uint32_t m = 0; m < tree.masters.size(); ++m) {
    NodeRange range;
    range.begin = static_cast<std::uint32_t>(h.nodes.size());
    h.nodes.push_back({});
    h.nodes.back().kind = NodeKind::master;
    flattener.add(tree.masters[m], 1, m);
    range.end = static_cast<std::uint32_t>(h.nodes.size());
    h.master_ranges.push_back(range);
    h.master_light_counts.push_back(flattener.take_light_count());
  }
  NodeRange root_range;
  root_range.begin = static_cast<std::uint32_t>(h.nodes.size());
  flattener.add(tree.root, 0, static_cast<std::uint32_t>(tree.masters.size()));
  root_range.end = static_cast<std::uint32_t>(h.nodes.size());
  h.master_ranges.push_back(root_range);
  h.root = root_range.begin;
  h.light_count = flattener.take_light_count();
  attach_aggregates(h);
  return h;
}

ExtentVolumes fit_extent_volumes(const LightHierarchy& h, float tolerance) {
  ExtentVolumes fitted;
  fitted.tolerance = tolerance;
  fitted.nodes.resize(h.nodes.size());
  std::vector<FittedNode>& out = fitted.nodes;
  for (const NodeRange& range : h.master_ranges) {
    for (std::uint32_t i = range.end; i-- > range.begin;) {
      const HierarchyNode& node = h.nodes[i];
      out[i].node = node;
      Bounds& volume = out[i].volume;
      switch (node_role(node)) {
        case NodeRole::light:
          volume = pad_bounds(light_extent_bounds(leaf_light(h, node), tolerance), kVolumePadding);
          break;
        case NodeRole::transform:
          volume =
              pad_bounds(transform_bounds(out[only_child(node, i)].volume, node_transform(h, node)),
                         kVolumePadding);
          break;
        case NodeRole::bounded:
        case NodeRole::reference:
          volume = out[only_child(node, i)].volume;
          break;
        case NodeRole::group: {
          Bounds b;
          for (const std::uint32_t child : group_children(h, node)) b = merge(b, out[child].volume);
          volume = b;
          break;
        }
      }
    }
  }
  return fitted;
}

std::size_t hierarchy_bytes(const LightHierarchy& h) {
  return h.nodes.size() * (sizeof(HierarchyNode) + sizeof(Bounds)) +
         h.union_children.size() * sizeof(std::uint32_t) +
         h.transforms.size() * sizeof(Similarity) + h.lights.size() * sizeof(Light) +
         h.aggregates.size() * sizeof(LightAggregate) + h.master_ranges.size() * sizeof(NodeRange) +
         h.master_light_counts.size() * sizeof(std::uint64_t);
}

}  // namespace lev
