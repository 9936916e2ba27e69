#include "app/scene_loading.h"

#include <chrono>

#include "scenes/scene_models.h"

namespace app {
namespace {

const scenes::SceneModel& model_for(const Settings& settings) {
  const scenes::SceneModel* model = scenes::find_scene_model(settings.scene);
  if (!model) {
    throw UsageError("--scene: must be one of " + scenes::scene_model_names("|") + ", got '" +
                     settings.scene + "'");
  }
  return *model;
}

}  // namespace

void apply_light_count(Settings& settings, std::uint64_t lights) {
  const scenes::SceneModel& model = model_for(settings);
  const int level = scenes::level_for_light_count(model, lights);
  if (level < 0) {
    throw UsageError("--lights: " + std::string(model.name) + " has " + scenes::light_counts_text(model) +
                     " lights, got '" + std::to_string(lights) + "'");
  }
  settings.level = level;
}

std::unique_ptr<LoadedScene> load_scene(const Settings& settings) {
  const scenes::SceneModel& model = model_for(settings);
  if (settings.level < model.min_level || settings.level > model.max_level) {
    throw UsageError("--level: " + std::string(model.name) + " has levels " +
                     std::to_string(model.min_level) + ".." + std::to_string(model.max_level) +
                     ", got '" + std::to_string(settings.level) + "'");
  }
  const auto start = std::chrono::steady_clock::now();
  auto loaded = std::make_unique<LoadedScene>();
  loaded->scene = model.build(settings.level);
  loaded->rays = std::make_unique<renderer::RayScene>(loaded->scene.geometry);
  loaded->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

}  // namespace app
