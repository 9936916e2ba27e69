// Scene Model 3 (thesis 5.3, fig. 5.3): a performance hall whose ceiling rig holds a grid of
// spotlights, all aimed at the stage where three robots ride unicycles. Level 3 has an 8x8 grid
// of 64 spotlights; each further level replaces every spotlight by four smaller ones, a quarter
// of the intensity each (a scale of 1/2, thesis 4.2.2), around the same aim, so the stage gets
// the same light at every level: 4^L spotlights (64, 256, ..., 16,384 for L = 3..7). Every object
// on the stage is lit by most of the lights, the case LEV is not made for (thesis 5.4.2.2): once
// the lights are many and weak, each falls below the tolerance while together they still light
// the stage.
// The light hierarchy groups the rig 2x2 into blocks and the blocks into quadrants, and splits
// each fixture by pure translations, so that a point out of the lights' reach costs a few box
// tests rather than one per fixture.
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kHallMinLevel = 3;
inline constexpr int kHallMaxLevel = 8;
inline constexpr float kRigHeight = 10.5f;
inline constexpr float kRigSpacing = 3.0f;  // between the level-3 spotlights
inline constexpr float kSpotConeDegrees = 60.0f;
inline constexpr float kSpotDropoff = 1.0f;
// A level-3 spotlight. Calibrated after thesis Table 7: at tolerance 0.01 every level-3 spotlight
// that reaches a shading point passes the tolerance there, about 80% of level 4's, about 15% of
// level 5's and almost none from level 6 on (a quarter of the intensity per level), while the
// stage stays as bright as at level 3.
inline constexpr float kSpotIntensity = 30.0f;

std::uint64_t hall_light_count(int level);
// Levels kHallMinLevel..kHallMaxLevel; throws std::invalid_argument otherwise.
SceneDescription describe_hall(int level);
renderer::Scene build_hall(int level);  // instantiate_scene(describe_hall(level))

}  // namespace scenes
