// The table of built-in scene models (thesis 5.3): name, levels and light counts, the function
// that describes a level (what `levrt export` writes) and the one that builds it (the description
// instantiated). The CLI and the viewer list this table; the benchmarks name the scenes they
// measure (app/bench/runner.h) and take their levels and builders from it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace scenes {

// The level every model opens at (the viewer's and the CLI's default).
inline constexpr int kDefaultSceneLevel = 3;
// Where the thesis measured its headline speedups (Tables 1, 2): the largest building and maze.
inline constexpr std::uint64_t kBuildingHeadlineLights = 16384;
inline constexpr std::uint64_t kMazeHeadlineLights = 12285;

struct SceneModel {
  const char* name;
  const char* label;
  int min_level;
  int max_level;
  int default_level;
  std::function<std::uint64_t(int level)> light_count;
  std::function<renderer::Scene(int level)> build;
  std::function<SceneDescription(int level)> describe;
};

const std::vector<SceneModel>& scene_models();
const SceneModel* find_scene_model(std::string_view name);
std::string scene_model_names(const char* separator);
// The level of `model` with exactly `lights` lights, or -1.
int level_for_light_count(const SceneModel& model, std::uint64_t lights);
// "64, 256, 1024, ..." for error messages.
std::string light_counts_text(const SceneModel& model);

}  // namespace scenes
