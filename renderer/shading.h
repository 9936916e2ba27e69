// Whitted ray tracing with Phong + Warn shading (thesis eq. 7): ambient, the direct term from
// the selected many-light method, and recursive reflection and refraction to a depth limit.
#pragma once

#include <atomic>
#include <cstdint>

#include <glm/glm.hpp>

#include "lev/light_selector.h"
#include "renderer/camera.h"
#include "renderer/ray_log.h"
#include "renderer/ray_scene.h"
#include "renderer/scene.h"

namespace renderer {

struct PathCounters {
  std::uint64_t shading_points = 0;
  lev::SelectionCounters selection;
};

struct TraceContext {
  const Scene& scene;
  const RayScene& rays;
  const lev::LightSelector& selector;
  lev::SelectorScratch& scratch;
  int max_depth = 5;  // secondary bounces after the primary hit
  std::vector<LoggedRay>* ray_log = nullptr;  // when set, every ray cast is appended (ray_log.h)
  // When set and raised, the trace stops casting (what it returns is then discarded by the caller).
  const std::atomic<bool>* cancel = nullptr;
};

// Reflection and refraction stop where the path weight (the product of kr and kt along the path)
// times the brightest value a pixel shows (1, framebuffer.h clamps there) is below half an 8-bit
// step: such a branch cannot change an output byte from a scene of radiances up to 1, so depth
// 64 costs no more than it can show (docs/extremes.md).
inline constexpr float kBrightestPixelValue = 1.0f;
inline constexpr float kSmallestVisibleWeight = 0.5f / 255.0f / kBrightestPixelValue;

// Radiance arriving along the ray; depth 0 is the primary ray, path_weight the factor the caller
// scales the result by (1 for a primary ray).
glm::vec3 trace_radiance(TraceContext& context, const Ray& ray, int depth, PathCounters& counters,
                         float path_weight = 1.0f);

}  // namespace renderer
