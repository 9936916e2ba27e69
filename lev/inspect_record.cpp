#include "lev/inspect_record.h"

#include <stdexcept>

#include "lev/hierarchy_cursor.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"
#include "lev/transform.h"

namespace lev {
namespace {

// Every light of the subtree at `node`, entered with world_from_local, in world space (instances
// expanded), each recorded as culled (or clustered) by `by`. Stops early once *cancel is raised
// (read every kCancelCheckLights lights).
void inspect_subtree(const LightHierarchy& h, std::uint32_t node,
                     const Similarity& world_from_local, std::uint32_t by, ShadingPoint& point,
                     std::vector<InspectedLight>& out, const std::atomic<bool>* cancel) {
  std::vector<SubtreePart> parts;
  for_each_subtree_light(h, node, world_from_local, parts, [&](const Light& light) {
    out.push_back(inspect_light(light, by, point));
    return !(cancel && out.size() % kCancelCheckLights == 0 &&
             cancel->load(std::memory_order_relaxed));
  });
}

}  // namespace

const char* role_name(InspectRole role) {
  switch (role) {
    case InspectRole::tested:
      return "tested";
    case InspectRole::sampled:
      return "sampled";
    case InspectRole::cluster:
      return "cluster";
    case InspectRole::estimated:
      return "estimated";
  }
  return "?";
}

void InspectRecord::attach_walk_clusters(std::size_t offset) {
  for (WalkCluster& cluster : walk_clusters) {
    if (offset + cluster.index >= shaded.size())
      throw std::logic_error("inspect: a walk's cluster was not shaded");
    ShadedLight& shaded_light = shaded[offset + cluster.index];
    shaded_light.role = InspectRole::cluster;
    shaded_light.node = cluster.whole_subtree ? cluster.subtree.node : kOwnTest;
    shaded_light.walk_cluster = static_cast<int>(&cluster - walk_clusters.data());
  }
}

InspectedLight inspect_light(const Light& world_light, std::uint32_t node, ShadingPoint& point) {
  InspectedLight inspected;
  inspected.light = world_light;
  inspected.node = node;
  inspected.unshadowed_radiance = point.unshadowed_radiance(world_light);
  inspected.visible =
      inspected.unshadowed_radiance != glm::vec3(0.0f) && point.visible(world_light);
  return inspected;
}

void complete_inspection(const LightHierarchy& hierarchy, ShadingPoint& point,
                         InspectRecord& record, const std::atomic<bool>* cancel) {
  record.culled.clear();
  for (const SubtreeRef& subtree : record.culled_subtrees) {
    inspect_subtree(hierarchy, subtree.node, subtree.world_from_local, subtree.node, point,
                    record.culled, cancel);
  }
  for (const Light& light : record.culled_lights)
    record.culled.push_back(inspect_light(light, kOwnTest, point));
  // A walk's cluster's lights, found again from what it stands for.
  for (ShadedLight& shaded : record.shaded) {
    if (shaded.role == InspectRole::estimated && shaded.members.empty()) {
      // AST's estimate of one light: the light itself, now with its shadow ray.
      shaded.members.push_back(inspect_light(shaded.light, kOwnTest, point));
      continue;
    }
    if (shaded.walk_cluster < 0) continue;
    const WalkCluster& cluster =
        record.walk_clusters[static_cast<std::size_t>(shaded.walk_cluster)];
    if (cluster.whole_subtree) {
      inspect_subtree(hierarchy, cluster.subtree.node, cluster.subtree.world_from_local,
                      cluster.subtree.node, point, shaded.members, cancel);
    } else {
      shaded.members.push_back(inspect_light(cluster.single, kOwnTest, point));
    }
  }
}

}  // namespace lev
