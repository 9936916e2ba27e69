// A render of a deterministic method may shade with rt's loop instead (issue 23): where the
// method's culling admits most lights, its walk or cut comes on top of nearly all of rt's shadow
// rays, and the method is then slower than rt without being exact. Before the first pass a probe
// shades the first hits of a fixed grid of pixel centres with the method, counting its work
// (shadow rays, extent volumes tested, lights tested), and counts there, without casting, the
// shadow rays rt would cast. Each side's counts are turned into shadow rays by its method row's
// WorkCost (lev/methods.h); when the method's come to at least rt's, the render shades with rt.
// rt's rays are counted only when its scan of every light alone costs less than the method's
// work (among a million lights, a walk that culls well settles it with 16 points of its own).
// The choice reads counts alone, never a clock, and the same pixels whatever the thread count,
// tile size or subsample: the image stays deterministic.
#pragma once

#include <cstddef>

#include "lev/light_selector.h"
#include "renderer/ray_scene.h"
#include "renderer/scene.h"

namespace renderer {

struct RenderSettings;  // render.h

// The probe's grid is at most this many pixel centres a side, fewer where the lights are so many
// that counting rt's rays at every probe point would cost more than kProbeLightBudget lights.
inline constexpr int kProbeGridSide = 8;
inline constexpr int kMinProbeGridSide = 2;
inline constexpr double kProbeLightBudget = 16.0 * 1024.0 * 1024.0;

struct RtFallbackProbe {
  int points = 0;                 // primary rays cast (one that hits nothing costs neither)
  double method_cost_rays = 0.0;  // the method's work per probe point, in shadow rays
  double rt_cost_rays = 0.0;      // rt's, likewise, or its lower bound (below)
  // rt_cost_rays is rt's scan of every light alone, which was already more than the method's
  // work: rt's shadow rays were not counted.
  bool rt_cost_is_lower_bound = false;
  bool use_rt = false;  // the render shades with rt's loop
};

// The probe grid's side for a scene of `light_count` lights.
int probe_grid_side(std::size_t light_count);

// Probes the frame of `settings` (its size, camera and exposure; not its threads, tiles or
// subsample) with `selector`, the method's selector for those settings. The selector must not
// learn between passes (a learning one is probed through a copy made for the probe).
RtFallbackProbe probe_rt_fallback(const Scene& scene, const RayScene& rays,
                                  const RenderSettings& settings,
                                  const lev::LightSelector& selector);

}  // namespace renderer
