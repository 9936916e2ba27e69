#include "lev/light_bvh.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace lev {
namespace {

constexpr std::size_t kLeafSize = 4;

using Iter = std::vector<std::uint32_t>::iterator;

// Splits [begin, end) at its median along the widest axis of the light positions.
Iter split_at_median(const std::vector<Light>& lights, Iter begin, Iter end) {
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (Iter it = begin; it != end; ++it) {
    lo = glm::min(lo, lights[*it].position);
    hi = glm::max(hi, lights[*it].position);
  }
  const glm::vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  Iter mid = begin + (end - begin) / 2;
  std::nth_element(begin, mid, end, [&](std::uint32_t a, std::uint32_t b) {
    const float pa = lights[a].position[axis], pb = lights[b].position[axis];
    return pa < pb || (pa == pb && a < b);
  });
  return mid;
}

LightTreeNode build(const std::vector<Light>& lights, Iter begin, Iter end) {
  const auto count = static_cast<std::size_t>(end - begin);
  if (count == 1) return light_node(lights[*begin]);
  std::vector<LightTreeNode> children;
  if (count <= kLeafSize) {
    // Keep the input order inside a leaf so a sorted list stays sorted.
    std::vector<std::uint32_t> leaf(begin, end);
    std::sort(leaf.begin(), leaf.end());
    for (std::uint32_t i : leaf) children.push_back(light_node(lights[i]));
  } else {
    const Iter mid = split_at_median(lights, begin, end);
    const Iter left_mid = split_at_median(lights, begin, mid);
    const Iter right_mid = split_at_median(lights, mid, end);
    for (auto [b, e] : {std::pair{begin, left_mid}, std::pair{left_mid, mid},
                        std::pair{mid, right_mid}, std::pair{right_mid, end}}) {
      if (b != e) children.push_back(build(lights, b, e));
    }
  }
  return extent_volume_node(union_node(std::move(children)));
}

}  // namespace

LightTreeNode build_light_bvh(const std::vector<Light>& lights) {
  if (lights.empty()) return union_node({});
  std::vector<std::uint32_t> order(lights.size());
  std::iota(order.begin(), order.end(), 0u);
  return build(lights, order.begin(), order.end());
}

}  // namespace lev
