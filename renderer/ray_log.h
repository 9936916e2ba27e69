// The rays a render casts, recorded so that they can be cast again with nothing else around
// them: no selection, no shading, just Embree. `levrt bench`'s `limit` experiment compares the
// whole render with that bare loop on the very same rays, which says how close levrt runs to the
// ray-casting limit of the machine.
//
// Recording is off unless a log is attached (record_rays in render.h); the render then costs one
// predictable branch per ray more. Each tile appends to its own list, so recording needs no lock
// and the log's order does not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/ray_scene.h"

namespace renderer {

enum class RayKind : std::uint32_t {
  closest_hit,  // primary, reflected and refracted rays (rtcIntersect1)
  shadow,       // shadow rays (rtcOccluded1 up to max_distance)
};

struct LoggedRay {
  glm::vec3 origin{0.0f};
  float max_distance = 0.0f;  // shadow rays; closest-hit rays search to infinity
  glm::vec3 direction{0.0f};
  RayKind kind = RayKind::closest_hit;
};

struct RayLog {
  std::vector<std::vector<LoggedRay>> tiles;  // one list per tile of the render
};

struct RayLogTotals {
  std::uint64_t closest_hit = 0;
  std::uint64_t shadow = 0;
};
RayLogTotals count_logged_rays(const RayLog& log);

struct BareCastResult {
  double seconds = 0.0;        // wall time of the casting loop
  std::uint64_t hits = 0;      // closest-hit rays that hit something
  std::uint64_t occluded = 0;  // shadow rays that were blocked
};

// Casts every logged ray again with bare Embree calls, tile by tile on `threads` workers
// (0 = all cores), the way the render spreads its tiles.
BareCastResult cast_logged_rays(const RayScene& rays, const RayLog& log, int threads);

}  // namespace renderer
