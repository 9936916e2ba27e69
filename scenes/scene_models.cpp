#include "scenes/scene_models.h"

#include "scenes/building.h"
#include "scenes/ceiling_grid.h"
#include "scenes/hall.h"
#include "scenes/lamp_street.h"
#include "scenes/maze.h"
#include "scenes/stage_rig.h"

namespace scenes {

const std::vector<SceneModel>& scene_models() {
  static const std::vector<SceneModel> models = {
      {"building", "Building (Scene Model 1)", kBuildingMinLevel, kBuildingMaxLevel,
       kDefaultSceneLevel, building_light_count, build_building, describe_building},
      {"maze", "Maze (Scene Model 2)", kMazeMinLevel, kMazeMaxLevel, kDefaultSceneLevel,
       maze_light_count, build_maze, describe_maze},
      {"hall", "Hall (Scene Model 3)", kHallMinLevel, kHallMaxLevel, kDefaultSceneLevel,
       hall_light_count, build_hall, describe_hall},
      // The classes of many dim lights; each file is a generator with parameters.
      {"stage", "Stage rig (coloured spots, mirror, glass)", kStageRigMinLevel, kStageRigMaxLevel,
       kDefaultSceneLevel, stage_rig_light_count, build_stage_rig, describe_stage_rig},
      {"carpark", "Car park (ceiling grid, partitions)", kCeilingGridMinLevel, kCeilingGridMaxLevel,
       kDefaultSceneLevel, ceiling_grid_light_count, build_ceiling_grid, describe_ceiling_grid},
      {"street", "Lamp street (instanced lamps)", kLampStreetMinLevel, kLampStreetMaxLevel,
       kDefaultSceneLevel, lamp_street_light_count, build_lamp_street, describe_lamp_street},
      {"street_bare", "Lamp street (lights written bare)", kLampStreetMinLevel, kLampStreetMaxLevel,
       kDefaultSceneLevel, lamp_street_light_count, build_bare_lamp_street,
       describe_bare_lamp_street},
  };
  return models;
}

const SceneModel* find_scene_model(std::string_view name) {
  for (const SceneModel& m : scene_models()) {
    if (name == m.name) return &m;
  }
  return nullptr;
}

std::string scene_model_names(const char* separator) {
  std::string s;
  for (const SceneModel& m : scene_models()) {
    if (!s.empty()) s += separator;
    s += m.name;
  }
  return s;
}

int level_for_light_count(const SceneModel& model, std::uint64_t lights) {
  for (int level = model.min_level; level <= model.max_level; ++level) {
    if (model.light_count(level) == lights) return level;
  }
  return -1;
}

std::string light_counts_text(const SceneModel& model) {
  std::string s;
  for (int level = model.min_level; level <= model.max_level; ++level) {
    if (!s.empty()) s += ", ";
    s += std::to_string(model.light_count(level));
  }
  return s;
}

}  // namespace scenes
