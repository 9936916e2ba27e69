// What a method did at one shading point, for the pixel inspector (`levrt inspect`, the viewer's
// inspector panel): the lights it shaded (tested, drawn, a cluster's representative, or AST's
// estimate), the subtrees and lights its walk culled, and the clusters it stood in for. The
// selectors fill it from their own walk and shading loop when SelectorScratch::inspect is set
// (null in renders, where recording costs one predictable branch per culled part), so what it
// lists is what the render did. complete_inspection then expands what was culled or clustered into
// single lights with their unshadowed radiance and an on-demand shadow ray each: the light the
// method lost, with shadows.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lev/important_lights.h"
#include "lev/light.h"

namespace lev {

class ShadingPoint;  // light_selector.h

// The node a light was culled by when no subtree culled it: its own irradiance test (or, for
// methods without a hierarchy, the method's test of that light).
inline constexpr std::uint32_t kOwnTest = ~0u;

// How a shaded light entered the direct radiance.
enum class InspectRole : std::uint8_t {
  tested,     // a shadow-tested light, counted at weight 1
  sampled,    // a draw of a sampling method, weighed by 1/(k x probability)
  cluster,    // a cluster's representative (carrying the cluster's intensity), one shadow ray
  estimated,  // AST's untested rest: its unshadowed radiance times a hit ratio, no ray
};

const char* role_name(InspectRole role);

// A light of the scene at the point: what it would give unshadowed, whether a shadow ray finds
// it, and the node that culled it (for a culled light or a cluster member).
struct InspectedLight {
  Light light;  // world space
  std::uint32_t node = kOwnTest;
  glm::vec3 unshadowed_radiance{0.0f};
  bool visible = false;  // by complete_inspection's shadow ray (false when it adds nothing)
  glm::vec3 visible_radiance() const { return visible ? unshadowed_radiance : glm::vec3(0.0f); }
};

// One term of the method's direct radiance.
struct ShadedLight {
  Light light;  // world space; a cluster's representative
  InspectRole role = InspectRole::tested;
  glm::vec3 unshadowed_radiance{0.0f};
  bool shadow_ray = false;  // cast (a light behind the surface needs none)
  bool visible = false;
  double weight = 1.0;                  // the factor on the visible radiance (1/(k p), a hit ratio)
  glm::vec3 contribution{0.0f};         // what it added to the direct radiance
  std::uint32_t node = kOwnTest;        // a cluster's node (hierarchy, or Lightcuts' tree)
  std::vector<InspectedLight> members;  // a cluster's lights (complete_inspection)
  int walk_cluster = -1;                // a walk's cluster: its index in walk_clusters
};

// A cluster the walk made, before complete_inspection: the index of its representative in the
// list the walk appended it to, and what it stands for (a culled subtree or a single light).
struct WalkCluster {
  std::size_t index = 0;
  bool whole_subtree = false;
  SubtreeRef subtree;
  Light single;
};

struct InspectRecord {
  std::vector<ShadedLight> shaded;  // in the order the method shaded them
  // What the walk culled (hierarchy subtrees, each with its frame, and single lights), and the
  // clusters it made, pending until complete_inspection.
  std::vector<SubtreeRef> culled_subtrees;
  std::vector<Light> culled_lights;
  std::vector<WalkCluster> walk_clusters;
  // Filled by complete_inspection: every light the method neither shaded nor clustered.
  std::vector<InspectedLight> culled;

  // Forget what a walk recorded (a method that walks again, lev_est).
  void clear_walk() {
    culled_subtrees.clear();
    culled_lights.clear();
    walk_clusters.clear();
  }
  // The walk's clusters' representatives now sit in `shaded` from `offset` on, in the order
  // of the list the walk appended them to: marks them as clusters with what they stand for.
  void attach_walk_clusters(std::size_t offset);
};

// Expands what `record` holds as culled subtrees, culled lights and clusters into single lights
// (InspectRecord::culled, ShadedLight::members), each with its unshadowed radiance at `point` and
// a shadow ray where that is not zero. hierarchy: the one the walk culled (subtree nodes refer to
// it). The rays are the inspector's own: nothing the method counted. cancel (may be null) is
// read every kCancelCheckLights lights; once raised the lists are left incomplete.
void complete_inspection(const LightHierarchy& hierarchy, ShadingPoint& point,
                         InspectRecord& record, const std::atomic<bool>* cancel = nullptr);

// A light of the scene as InspectedLight, measured at `point` (one shadow ray when it adds).
InspectedLight inspect_light(const Light& world_light, std::uint32_t node, ShadingPoint& point);

}  // namespace lev
