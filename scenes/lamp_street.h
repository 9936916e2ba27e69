// Scene class "lamp street": a town of parallel streets lit by one lamp design placed
// thousands of times, each lamp an `instance` of one master (post, arm, head and a spotlight
// shining down) under a translation and a turn, all of them children of one union. The scene
// format puts no box above them; light_description_conversion gives the union its automatic
// hierarchy over the instances, keeping the master shared. The same town with the lights written
// bare
// (`instanced` false: the master holds the lamp's geometry only, every light stands in the root
// union where the instance would place it) is the yardstick of that hierarchy.
// Parameters make other towns of the class; the model's level L has 2^(L-2) streets with
// 2^(L+1) lamps on each side: 4^L lamps (64, 256, 1,024, 4,096, 16,384 for L = 3..7).
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kLampStreetMinLevel = 3;
inline constexpr int kLampStreetMaxLevel = 7;

struct LampStreetParams {
  int streets = 2;                 // parallel, along x
  int lamps_per_side = 16;         // on each side of a street
  float lamp_spacing_m = 4.0f;     // along a street
  float street_spacing_m = 26.0f;  // between street centres; houses stand in between
  float lamp_height_m = 6.0f;
  // A lamp's spotlight, shining down. At tolerance 0.01 a point on a street tests about three
  // dozen lamps (the nearest on its street and the next).
  float lamp_intensity = 9.0f;
  float cone_degrees = 70.0f;
  float dropoff = 1.5f;
  std::uint64_t seed = 1;  // house heights and colours
  bool instanced = true;
};

std::uint64_t lamp_street_light_count(int level);
LampStreetParams lamp_street_params(int level);  // throws std::invalid_argument out of range
// Throws std::invalid_argument for counts below 1 or sizes not above 0.
SceneDescription describe_lamp_street_from(const LampStreetParams& params);
SceneDescription describe_lamp_street(int level);
SceneDescription describe_bare_lamp_street(int level);  // the same town, lights written bare
renderer::Scene build_lamp_street(int level);
renderer::Scene build_bare_lamp_street(int level);

}  // namespace scenes
