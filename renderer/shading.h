// Whitted ray tracing with Phong + Warn shading (thesis eq. 7): ambient, the direct term from
// the selected many-light method, and recursive reflection and refraction to a depth limit.
#pragma once

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
};

// Radiance arriving along the ray; depth 0 is the primary ray.
glm::vec3 trace_radiance(TraceContext& context, const Ray& ray, int depth, PathCounters& counters);

}  // namespace renderer
