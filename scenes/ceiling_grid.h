// Scene class "ceiling grid": a car park (or an open-plan office) lit by a flat grid of
// dim ceiling lights, one per parking bay, written as one flat list of lights, with full-height
// partition walls between rows of bays (gaps for the driving lanes), pillars and parked cars.
// A point on the floor is lit by the hundreds of lights around it, each a little, and walls hide
// many of those that reach it unshadowed.
// Parameters make other floors of the class; the model's level L has a 2^L x 2^L grid: 4^L
// lights (64, 256, 1,024, 4,096, 16,384 for L = 3..7).
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kCeilingGridMinLevel = 3;
inline constexpr int kCeilingGridMaxLevel = 7;

struct CeilingGridParams {
  int columns = 8;  // lights along x
  int rows = 8;     // lights along y
  float spacing_m = 2.5f;
  float ceiling_height_m = 2.6f;
  int bay_columns = 4;  // a partition wall after every this many columns of lights
  int lane_rows = 8;    // the walls leave a two-row lane after every this many rows
  // Each light a downward spot over the whole half-space below (cosine dropoff, like the
  // maze's streetlights), so every light reaches the floor: at tolerance 0.01 a floor point tests a
  // few dozen lights, at 0.001 a few hundred.
  float intensity = 3.0f;
  float cone_degrees = 90.0f;
  float dropoff = 1.0f;
  float car_share = 0.6f;  // of the bays that hold a car
  std::uint64_t seed = 1;  // which bays hold cars, and their colours
};

std::uint64_t ceiling_grid_light_count(int level);
CeilingGridParams ceiling_grid_params(int level);  // throws std::invalid_argument out of range
// Throws std::invalid_argument for counts below 1 or sizes not above 0.
SceneDescription describe_ceiling_grid_from(const CeilingGridParams& params);
SceneDescription describe_ceiling_grid(int level);
renderer::Scene build_ceiling_grid(int level);

}  // namespace scenes
