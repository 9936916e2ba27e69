// Scene Model 2 (thesis 5.3, fig. 5.2): a maze whose one corridor follows a Hilbert curve, with a
// robot on a unicycle under a streetlight every third of a cell along it. The curve is built the
// way it is defined, recursively: block k is four copies of block k-1 (two of them turned a
// quarter) joined by three corridor segments, so robots, streetlights and walls are instanced
// and the light hierarchy grows by a constant per level. Level L is the curve of order L+1:
// 4^(L+1) cells, 4^(L+1)-1 segments of three lights, 3*(4^(L+1)-1) lights (45, 189, 765, ...).
#pragma once

#include <cstdint>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr int kMazeMinLevel = 1;
inline constexpr int kMazeMaxLevel = 8;
inline constexpr float kMazeCell = 6.0f;       // corridor cell, wall to wall
inline constexpr float kMazeHalfWall = 0.15f;  // each cell owns half of a wall it has
inline constexpr float kMazeWallHeight = 2.0f;
inline constexpr float kStreetlightHeight = 3.2f;
// Streetlights are Warn spots pointing down, as the thesis' maze lights were (Test 2.4, Table 11
// measures them with cones of 25 to 90 degrees): the thesis' default cone of 90 degrees (ch. 4.2.2)
// with a cosine dropoff, so a lamp lights a pool under it and everything below its height, at
// grazing angles, which keeps every light non-zero at every point in the corridors (what `rt`
// tests) as with the thesis' maze.
inline constexpr float kStreetlightConeDegrees = 90.0f;
inline constexpr float kStreetlightDropoff = 1.0f;
// Calibrated so that at tolerance 0.01 a shading point tests about 19 lights at the larger levels
// (thesis Tables 9 and 14: 17 to 19).
inline constexpr float kStreetlightIntensity = 3.0f;

std::uint64_t maze_light_count(int level);
// Levels kMazeMinLevel..kMazeMaxLevel; throws std::invalid_argument otherwise.
SceneDescription describe_maze(int level);
renderer::Scene build_maze(int level);  // instantiate_scene(describe_maze(level))

}  // namespace scenes
