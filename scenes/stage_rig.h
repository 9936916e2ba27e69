// Scene class "stage rig": thousands of coloured spotlights, overlapping, all aimed at
// one stage on which a mirror and glass objects stand, written as one flat list of lights (the
// automatic hierarchy of light_description_conversion is all the structure they get). Every point
// on the stage is lit by a large share of the rig and each spot gives it little: the
// many-dim-lights case, with reflected and refracted rays that need their own selection. Parameters
// make other rigs of the class; the model's level L has 72 * 4^(L-3) spots (72, 288, 1,152, 4,608,
// 18,432 for L = 3..7), whose summed intensity is the same at every level.
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kStageRigMinLevel = 3;
inline constexpr int kStageRigMaxLevel = 7;

struct StageRigParams {
  int spots = 72;
  // The rig: spots spread over a truss this wide (x) and deep (y) at this height, and over two
  // side towers; each is aimed at a random point within aim_radius_m of the stage centre.
  float truss_width_m = 26.0f;
  float truss_depth_m = 14.0f;
  float truss_height_m = 9.0f;
  float aim_radius_m = 4.5f;
  float cone_min_degrees = 12.0f, cone_max_degrees = 30.0f;
  float dropoff_min = 2.0f, dropoff_max = 10.0f;
  // Summed over the rig and split evenly between the spots, so that every level lights the
  // stage alike.
  float total_intensity = 2400.0f;
  std::uint64_t seed = 1;  // positions, aims, cones and colours
};

std::uint64_t stage_rig_light_count(int level);
StageRigParams stage_rig_params(int level);  // throws std::invalid_argument out of range
// Throws std::invalid_argument for counts below 1 or sizes not above 0.
SceneDescription describe_stage_rig_from(const StageRigParams& params);
SceneDescription describe_stage_rig(int level);
renderer::Scene build_stage_rig(int level);

}  // namespace scenes
