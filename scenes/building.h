// Scene Model 1 (thesis 5.3, fig. 5.1): a square building of rooms, instanced 2x2 per level, with
// no roof. Every room has walls with doorways, one ceiling point light and two robots on
// unicycles. Level L has 4^L rooms and lights. The description instances a room master 2x2 per
// level (thesis fig. 3.4), so the light hierarchy grows by a constant per level.
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kBuildingMinLevel = 1;
inline constexpr int kBuildingMaxLevel = 10;
inline constexpr float kRoomSize = 10.0f;
inline constexpr float kWallHeight = 4.0f;
inline constexpr float kCeilingLightHeight = 3.8f;
// Calibrated so that at tolerance 0.01 a floor point tests about 40 lights inside a large
// building (extent radius sqrt(12.7 / 0.01) = 35.6 units, about 40 rooms), at 0.1 about 4 and
// at 0.001 about 400, as in thesis Table 12.
inline constexpr float kCeilingLightIntensity = 12.7f;

std::uint64_t building_light_count(int level);
// Levels kBuildingMinLevel..kBuildingMaxLevel; throws std::invalid_argument otherwise.
SceneDescription describe_building(int level);
renderer::Scene build_building(int level);  // instantiate_scene(describe_building(level))

}  // namespace scenes
