// Validation of a scene description, the first step of instantiating it (scene_instantiation.h):
// every value in range, every reference defined, no instance cycle, and the limits below that
// keep a description (in practice, a scene file) from exhausting memory, time or the stack. What
// validation learns on the way (an order of the masters and what each expands to) is what the
// later steps need, so it is returned rather than computed twice.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "scenes/scene_description.h"

namespace scenes {

// Each breach of a limit is reported with its own message.
inline constexpr std::size_t kMaxSceneNodes = std::size_t{1} << 22;
inline constexpr int kMaxNodeDepth = 100;     // nodes nested inside one master or the root
inline constexpr int kMaxInstanceDepth = 64;  // masters instancing masters
inline constexpr std::size_t kMaxMasters = 65536;
inline constexpr std::size_t kMaxMaterials = 65536;
inline constexpr std::uint64_t kMaxSceneLights = std::uint64_t{1} << 24;
inline constexpr std::uint64_t kMaxScenePlacements = std::uint64_t{1} << 22;  // Embree instances
inline constexpr std::uint64_t kMaxPrototypeTriangles = std::uint64_t{1} << 25;
inline constexpr float kMaxCoordinate = 1e6f;  // any position, length or radius
inline constexpr float kMinScale = 1e-6f;      // one affine node's scale
inline constexpr float kMaxScale = 1e6f;
inline constexpr double kMaxComposedScaleLog10 = 12.0;  // scales multiplied along any path
inline constexpr float kMaxIntensity = 1e12f;
inline constexpr int kMaxCylinderSegments = 1024;

// A master whose geometry, nested instances expanded, has at most this many triangles is baked
// into one prototype: fewer Embree instances trace faster, and the copies stay small.
inline constexpr std::uint64_t kBakeTriangleBudget = 16384;
// A master's or the root's light part with more atoms than this (its lights and placed
// instances, through any unions and transforms) gets an automatic hierarchy over them: a union
// has no volume to cull with.
inline constexpr std::size_t kMaxUnstructuredLights = 8;

// Throws std::invalid_argument "/json/path: problem (value)" for the first problem found: values
// out of range, wrong child counts, undefined masters or materials, instance cycles, limits.
// The path is where a scene file (scene_file.h) holds the offending value.
void validate_description(const SceneDescription& scene);

// What a subtree holds with every instance expanded (saturating counts), and what flattening
// it unbaked costs in Embree instances.
struct SubtreeTotals {
  std::uint64_t lights = 0;
  std::uint64_t triangles = 0;
  std::uint64_t direct_triangles = 0;  // primitives in this tree itself (not behind an instance)
  std::uint64_t site_placements = 0;   // Embree instances its instance nodes expand to
  int instance_depth = 0;              // longest chain of instances below
  double min_log_scale = std::numeric_limits<double>::infinity();  // log10 of composed scales
  double max_log_scale = -std::numeric_limits<double>::infinity();
};

// A valid description's masters: an order in which each comes after every master it instances,
// and what each expands to.
struct SceneAnalysis {
  std::vector<std::uint32_t> master_order;
  std::vector<SubtreeTotals> master_totals;  // by master index

  const std::vector<std::uint32_t>& order() const { return master_order; }
  const SubtreeTotals& master(std::uint32_t m) const { return master_totals[m]; }
  // Baked masters become one prototype each (kBakeTriangleBudget).
  bool baked(std::uint32_t m) const { return master_totals[m].triangles <= kBakeTriangleBudget; }
};

// validate_description, keeping what it learned. Throws as validate_description does.
SceneAnalysis analyze_description(const SceneDescription& scene);

}  // namespace scenes
