// Whitted ray tracing with Phong + Warn shading (thesis eq. 7): ambient, the direct term from
// the selected many-light method, and recursive reflection and refraction to a depth limit.
#pragma once

#include <atomic>
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "lev/light_selector.h"
#include "renderer/camera.h"
#include "renderer/ray_log.h"
#include "renderer/ray_scene.h"
#include "renderer/scene.h"

namespace renderer {

struct InspectedHit;  // pixel_inspection.h

struct PathCounters {
  std::uint64_t shading_points = 0;
  lev::SelectionCounters selection;
  // When TraceContext::compute_error_bound: an upper bound of |this radiance - rt's radiance|
  // per channel (error_bound.h), summed over the path's shading points as the radiance is.
  glm::vec3 error_bound{0.0f};
  // When TraceContext::missed_draws > 0: the estimated missed light (lev/missed_light.h) and
  // its variance, weighed by the path weight (squared for the variance) and summed as above.
  glm::vec3 missed{0.0f};
  glm::vec3 missed_variance{0.0f};
};

struct TraceContext {
  const Scene& scene;
  const RayScene& rays;
  const lev::LightSelector& selector;
  lev::SelectorScratch& scratch;
  int max_depth = 5;                          // secondary bounces after the primary hit
  std::vector<LoggedRay>* ray_log = nullptr;  // when set, every ray cast is appended (ray_log.h)
  // When set and raised, the trace stops casting (what it returns is then discarded by the caller).
  const std::atomic<bool>* cancel = nullptr;
  // Asks the selector for its culled irradiance bound and carries it into PathCounters::error_bound
  // (off: the selector skips that work).
  bool compute_error_bound = false;
  // > 0: asks the selector for the missed light with this many draws from missed_random (seeded
  // per pixel and pass by the caller), into PathCounters::missed.
  int missed_draws = 0;
  lev::RandomStream missed_random{};
  // When set (the pixel inspector, pixel_inspection.h), each shading point of the path appends
  // what the method did there, recorded by the selector itself; null in renders.
  std::vector<InspectedHit>* inspection = nullptr;
};

// Reflection and refraction stop where the path weight (the product of kr and kt along the path)
// times the brightest value a pixel shows (1, framebuffer.h clamps there) is below half an 8-bit
// step: such a branch cannot change an output byte from a scene of radiances up to 1, so depth
// 64 costs no more than it can show (docs/extremes.md).
inline constexpr float kBrightestPixelValue = 1.0f;
inline constexpr float kSmallestVisibleWeight = 0.5f / 255.0f / kBrightestPixelValue;

// The most a sample's radiance adds to its pixel: the largest float over 2^17, so that a pixel's
// sum over the most passes a render takes (100,000) stays finite, where two samples near the
// largest float (a light of 1e36 on a surface of kd 1e3) summed to +inf. Even at the lowest
// exposure (2^-64) it shows as white: no displayed value changes.
inline constexpr float kLargestSampleRadiance = std::numeric_limits<float>::max() / 131072.0f;
inline glm::vec3 clamp_sample_radiance(const glm::vec3& radiance) {
  return glm::min(radiance, glm::vec3(kLargestSampleRadiance));
}

// Radiance arriving along the ray; depth 0 is the primary ray, path_weight the factor the caller
// scales the result by (1 for a primary ray). Adds the work to counters and, when asked, the error
// bound of path_weight times the result (the pixel's units, as the recursion shares counters).
glm::vec3 trace_radiance(TraceContext& context, const Ray& ray, int depth, PathCounters& counters,
                         float path_weight = 1.0f);

}  // namespace renderer
