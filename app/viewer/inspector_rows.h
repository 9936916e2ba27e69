// The viewer's inspector: one pinned pixel's inspection (renderer/pixel_inspection.h),
// made by the render worker with the render's own settings, as the rows the inspector panel lists
// and the image overlays mark: the lights that give or would give the pixel the most, over every
// hit of its path, largest first, and the outline of a light's extent volume on the image.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lev/light.h"
#include "renderer/camera.h"
#include "renderer/pixel_inspection.h"

namespace app::viewer {

// One row: a shaded term (tested, sampled, a cluster's representative, an estimate) or a culled
// light, its values in pixel units (times the hit's path weight).
struct InspectorRow {
  int depth = 0;  // the hit: 0 the primary
  lev::Light light;
  std::string role;  // "tested", "sampled", "cluster", "estimated" or "culled"
  std::uint32_t node = lev::kOwnTest;
  std::size_t members = 0;  // a cluster's lights
  glm::vec3 unshadowed{0.0f};
  bool seen = false;         // its shadow ray found it (a culled light: the inspector's ray)
  glm::vec3 to_pixel{0.0f};  // contribution, or for a culled light what was lost
};

// The inspection of one pixel of one render, as the worker publishes it.
struct PublishedInspection {
  std::uint64_t generation = 0;  // the render (WorkerStatus::generation) it explains
  int x = 0, y = 0;
  renderer::Camera camera;  // the view's, for projecting lights onto the image
  int width = 0, height = 0;
  float tolerance = 0.0f;  // for the extent volumes' outlines
  renderer::InspectedTotals totals;
  std::vector<InspectorRow> rows;  // the top ones (renderer::ranks_before: largest first)
  std::size_t all_rows = 0;        // before the cut
  double seconds = 0.0;            // the inspection's time
};

inline constexpr std::size_t kInspectorRows = 50;

// The top `keep` rows of an inspection, over all its hits, in renderer::ranks_before's order
// (largest |to_pixel| first, a NaN value last, equal rows in the record's order).
std::vector<InspectorRow> inspector_rows(const renderer::PixelInspection& inspection,
                                         std::size_t keep, std::size_t* all_rows = nullptr);

// The radius of a light's extent volume at `tolerance` (world units; the sphere LEV culls by:
// sqrt(brightest intensity / tolerance), capped by its range); +inf at tolerance 0.
float extent_radius(const lev::Light& light, float tolerance);

// The outline of a light's extent volume on the image, in image pixels: a sphere's as a circle of
// points, a spot's as its cone (apex, the rim of its base circle and lines from the apex). Empty
// where nothing of it is in front of the camera.
std::vector<std::vector<glm::vec2>> extent_outline(const renderer::Camera& camera, int width,
                                                   int height, const lev::Light& light,
                                                   float tolerance);

}  // namespace app::viewer
