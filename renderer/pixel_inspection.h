// The pixel inspector's query (docs/design.md): one pixel's pass-0 sample traced as a
// render traces it (the same primary ray, random streams, selector and recursion), with each
// shading point's selector asked to record what it shaded, culled and clustered
// (lev/inspect_record.h). From the records, per hit and for the pixel: what the tested lights
// added, what the method lost against `rt` with shadows, and the certified bound.
#pragma once

#include <atomic>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "lev/inspect_record.h"
#include "renderer/render.h"
#include "renderer/shading.h"

namespace renderer {

// One shading point of the pixel's path: the primary hit (depth 0) or a reflected or refracted
// one, whose direct radiance reaches the pixel times path_weight.
struct InspectedHit {
  int depth = 0;
  float path_weight = 1.0f;
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};           // facing the incoming ray
  glm::vec3 direct_radiance{0.0f};  // the method's
  glm::vec3 error_bound{0.0f};      // certified, in pixel units (path weight applied)
  lev::InspectRecord record;
};

// What one hit's record adds up to, in pixel units (times the path weight).
struct InspectedTotals {
  glm::dvec3 tested{0.0};            // the method's direct radiance
  glm::dvec3 exact{0.0};             // rt's: every light's visible radiance
  glm::dvec3 lost{0.0};              // exact - tested: what the method lost, with shadows
  glm::dvec3 bound{0.0};             // the certified bound of |lost| (no shadows)
  std::size_t shaded = 0;            // terms the method shaded (lights tested, draws, clusters)
  std::size_t tested_lights = 0;     // single lights shadow-tested exactly
  std::size_t culled_lights = 0;     // lights neither tested nor clustered
  std::size_t clusters = 0;          // clusters and AST estimates
  std::size_t clustered_lights = 0;  // lights inside them
};

InspectedTotals hit_totals(const InspectedHit& hit);

struct PixelInspection {
  int x = 0, y = 0;
  glm::vec3 radiance{0.0f};  // the sample, as the render's pass 0 gives it
  PathCounters counters;
  std::vector<InspectedHit> hits;
  InspectedTotals totals;  // over the hits
};

// The order of the inspector's lists, largest first by what a row gives the pixel: a total order
// even where a value is NaN or infinite (a comparator that is not a strict weak order makes
// std::sort undefined). Rows compare by their largest |channel| to the pixel, then by their
// largest unshadowed channel (both descending, +inf first, NaN last), then by their place in the
// record (`order`: the order the method met the lights), so equal rows keep that order.
struct ContributionRank {
  double to_pixel = 0.0;    // largest |channel|; NaN when any channel is NaN
  double unshadowed = 0.0;  // the same of the unshadowed radiance
  std::size_t order = 0;
};

ContributionRank contribution_rank(const glm::dvec3& to_pixel, const glm::dvec3& unshadowed,
                                   std::size_t order);
// True when `a` is listed before `b`.
bool ranks_before(const ContributionRank& a, const ContributionRank& b);

// Traces pixel (x, y)'s pass-0 sample with `selector` (made for `settings`, as a render state
// makes it; a viewer passes its render's) and records every shading point. The certified bound is
// asked for as `levrt render` asks for it. Throws std::invalid_argument for a pixel outside the
// image. cancel (may be null) is read as a render reads it (the trace, the selector's loops) and
// between the inspector's own shadow rays; once raised the inspection returns early with lists
// the caller must discard.
PixelInspection inspect_pixel(const Scene& scene, const RayScene& rays,
                              const RenderSettings& settings, const lev::LightSelector& selector,
                              int x, int y, const std::atomic<bool>* cancel = nullptr);

}  // namespace renderer
