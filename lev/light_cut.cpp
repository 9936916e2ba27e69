#include "lev/light_cut.h"

#include <algorithm>
#include <limits>

namespace lev {
namespace {

// The heap's order: the largest bound on top; among equal bounds the lower node, so the cut
// never depends on how the standard library breaks ties.
bool smaller_bound(const CutEntry& a, const CutEntry& b) {
  return a.bound < b.bound || (a.bound == b.bound && a.node > b.node);
}

}  // namespace

glm::vec3 shade_light_cut(const LightCutTree& tree, const CutSettings& settings,
                          ShadingPoint& point, CutScratch& scratch, SelectionCounters& counters,
                          glm::vec3* culled_irradiance_bound, const std::atomic<bool>* cancel,
                          glm::vec3* cluster_error_bound) {
  std::vector<CutEntry>& heap = scratch.heap;
  std::vector<CutEntry>& final = scratch.final;
  heap.clear();
  final.clear();
  if (culled_irradiance_bound) *culled_irradiance_bound = glm::vec3(0.0f);
  if (cluster_error_bound) *cluster_error_bound = glm::vec3(0.0f);
  if (tree.nodes.empty()) return glm::vec3(0.0f);
  const FramePoint x = world_frame_point(point.position());
  const SurfaceResponse surface = point.surface_response();
  // At 0 the cut is exact: every cluster that could add anything is refined, whatever its size.
  const bool exact = !(settings.relative_error > 0.0f);
  const std::uint32_t max_size =
      exact ? std::numeric_limits<std::uint32_t>::max() : std::max(settings.max_size, 1u);

  // A node of the cut with its estimate; known_visibility is that of its representative when
  // its parent's shared it (one ray per representative, Walter et al. sec. 4.2).
  const auto evaluate = [&](std::uint32_t node, std::int8_t known_visibility) {
    CutEntry e;
    e.node = node;
    const CutTreeNode& n = tree.nodes[node];
    if (!n.is_leaf()) {
      glm::vec3 irradiance;
      e.radiance_bound = radiance_bound(n.aggregate, x, surface, &irradiance);
      e.bound = brightest(e.radiance_bound);
      if (e.bound == 0.0f) return e;  // no light of it can add anything here: no ray
      e.irradiance_bound = irradiance;
    }
    const Light light = cluster_light(tree, node);
    const glm::vec3 radiance = point.unshadowed_radiance(light);
    e.visibility = known_visibility;
    if (radiance == glm::vec3(0.0f)) return e;
    if (e.visibility < 0) {
      ++counters.shadow_rays;
      e.visibility = point.visible(light) ? 1 : 0;
    }
    if (e.visibility == 1) e.estimate = radiance;
    return e;
  };
  glm::dvec3 total(0.0);
  const auto add = [&](const CutEntry& e) {
    total += glm::dvec3(e.estimate);
    if (tree.nodes[e.node].is_leaf() || e.bound == 0.0f) {
      final.push_back(e);
    } else {
      heap.push_back(e);
      std::push_heap(heap.begin(), heap.end(), smaller_bound);
    }
  };

  add(evaluate(0, -1));
  std::uint32_t size = 1;
  while (!heap.empty() && size < max_size) {
    const float total_now = std::max(brightest(total), 0.0f);
    if (!exact && heap.front().bound <= settings.relative_error * total_now) break;
    if (cancel && size % kCancelCheckLights == 0 && cancel->load(std::memory_order_relaxed)) break;
    std::pop_heap(heap.begin(), heap.end(), smaller_bound);
    const CutEntry parent = heap.back();
    heap.pop_back();
    total -= glm::dvec3(parent.estimate);
    const CutTreeNode& node = tree.nodes[parent.node];
    for (const std::uint32_t child : node.children) {
      const bool shares = tree.nodes[child].representative == node.representative;
      add(evaluate(child, shares ? parent.visibility : std::int8_t{-1}));
    }
    ++size;
  }

  // The sum in the tree's light order (each cluster by its representative, which no other
  // cluster of the cut has): at relative error 0 the single lights in rt's order, summed as
  // sum_visible_lights sums them.
  final.insert(final.end(), heap.begin(), heap.end());
  std::sort(final.begin(), final.end(), [&](const CutEntry& a, const CutEntry& b) {
    return tree.nodes[a.node].representative < tree.nodes[b.node].representative;
  });
  glm::dvec3 sum(0.0), culled(0.0), error(0.0);
  for (const CutEntry& e : final) {
    sum += glm::dvec3(e.estimate);
    culled += glm::dvec3(e.irradiance_bound);
    // A single light is exact (its bounds are 0): no error.
    if (!tree.nodes[e.node].is_leaf()) error += glm::dvec3(glm::max(e.estimate, e.radiance_bound));
  }
  counters.lights_tested += final.size();
  if (culled_irradiance_bound) *culled_irradiance_bound = round_up_sum(culled);
  if (cluster_error_bound) *cluster_error_bound = round_up_sum(error);
  return glm::vec3(glm::min(sum, glm::dvec3(std::numeric_limits<float>::max())));
}

void record_light_cut(const LightCutTree& tree, const CutScratch& scratch, ShadingPoint& point,
                      InspectRecord& record) {
  std::vector<std::uint32_t> below;
  for (const CutEntry& e : scratch.final) {
    ShadedLight& shaded = record.shaded.emplace_back();
    shaded.light = cluster_light(tree, e.node);
    shaded.node = e.node;
    shaded.unshadowed_radiance = point.unshadowed_radiance(shaded.light);
    shaded.shadow_ray = e.visibility >= 0;
    shaded.visible = e.visibility == 1;
    shaded.contribution = e.estimate;
    if (tree.nodes[e.node].is_leaf()) continue;
    shaded.role = InspectRole::cluster;
    below.assign(1, e.node);
    while (!below.empty()) {
      const CutTreeNode& n = tree.nodes[below.back()];
      below.pop_back();
      if (n.is_leaf()) {
        shaded.members.push_back(inspect_light(tree.lights[n.representative], e.node, point));
      } else {
        below.push_back(n.children[1]);
        below.push_back(n.children[0]);
      }
    }
  }
}

}  // namespace lev
