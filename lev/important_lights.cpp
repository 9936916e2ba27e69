#include "lev/important_lights.h"

#include "lev/bounds.h"

namespace lev {
namespace {

// One walk for both the query (cull = true) and the flattening (cull = false): sharing it is what
// makes `lev` at tolerance 0 and `rt` see bit-identical world-space lights.
template <bool kCull>
void walk(const LightHierarchy& h, const glm::vec3& point, WalkScratch& scratch,
          std::vector<Light>& out, WalkCounters& counters) {
  std::vector<WalkFrame>& stack = scratch.stack;
  stack.clear();
  stack.push_back({Similarity{}, point, h.root});
  while (!stack.empty()) {
    WalkFrame f = stack.back();
    stack.pop_back();
    for (;;) {
      const HierarchyNode& node = h.nodes[f.node];
      bool descend = false;
      switch (node.kind) {
        case NodeKind::point_light:
        case NodeKind::spot_light: {
          const Light world = transform_light(h.lights[node.payload], f.world_from_local);
          if constexpr (kCull) {
            ++counters.nodes_visited;
            if (is_important(world, point, h.tolerance)) out.push_back(world);
          } else {
            out.push_back(world);
          }
          break;
        }
        case NodeKind::affine: {
          const Similarity& xf = h.transforms[node.payload];
          f.world_from_local = compose(f.world_from_local, xf);
          if constexpr (kCull) f.local_point = apply_inverse_point(xf, f.local_point);
          f.node += 1;
          descend = true;
          break;
        }
        case NodeKind::extent_volume:
        case NodeKind::master:
          if constexpr (kCull) {
            ++counters.nodes_visited;
            if (!contains(node.volume, f.local_point)) break;
          }
          f.node += 1;
          descend = true;
          break;
        case NodeKind::instance:
          f.node = node.payload;
          descend = true;
          break;
        case NodeKind::set_union: {
          const std::uint32_t count = h.union_children[node.payload];
          // Pushed last-first so the first child is walked first (depth-first, left to right).
          for (std::uint32_t k = count; k-- > 0;) {
            WalkFrame child = f;
            child.node = h.union_children[node.payload + 1 + k];
            stack.push_back(child);
          }
          break;
        }
      }
      if (!descend) break;
    }
  }
}

}  // namespace

void find_important_lights(const LightHierarchy& hierarchy, const glm::vec3& point,
                           WalkScratch& scratch, std::vector<Light>& important_lights,
                           WalkCounters& counters) {
  walk<true>(hierarchy, point, scratch, important_lights, counters);
}

std::vector<Light> flatten_lights(const LightHierarchy& hierarchy) {
  std::vector<Light> lights;
  lights.reserve(hierarchy.light_count);
  WalkScratch scratch;
  WalkCounters counters;
  walk<false>(hierarchy, glm::vec3(0.0f), scratch, lights, counters);
  return lights;
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
