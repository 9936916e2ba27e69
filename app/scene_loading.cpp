#include "app/scene_loading.h"

#include <chrono>

#include "scenes/scene_file.h"
#include "scenes/scene_instantiation.h"
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

bool is_scene_file(const Settings& settings) { return scenes::is_scene_file_name(settings.scene); }

void apply_light_count(Settings& settings, std::uint64_t lights) {
  if (is_scene_file(settings)) {
    throw UsageError("--lights: a scene file has the lights it describes, got '" + std::to_string(lights) + "'");
  }
  const scenes::SceneModel& model = model_for(settings);
  const int level = scenes::level_for_light_count(model, lights);
  if (level < 0) {
    throw UsageError("--lights: " + std::string(model.name) + " has " + scenes::light_counts_text(model) +
                     " lights, got '" + std::to_string(lights) + "'");
  }
  settings.level = level;
}

scenes::SceneDescription describe_scene(const Settings& settings) {
  if (is_scene_file(settings)) return scenes::load_scene_file(settings.scene);
  const scenes::SceneModel& model = model_for(settings);
  if (settings.level < model.min_level || settings.level > model.max_level) {
    throw UsageError("--level: " + std::string(model.name) + " has levels " +
                     std::to_string(model.min_level) + ".." + std::to_string(model.max_level) +
                     ", got '" + std::to_string(settings.level) + "'");
  }
  return model.describe(settings.level);
}

std::unique_ptr<LoadedScene> load_scene(const Settings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const scenes::SceneDescription description = describe_scene(settings);
  auto loaded = std::make_unique<LoadedScene>();
  loaded->scene = scenes::instantiate_scene(description);
  loaded->rays = std::make_unique<renderer::RayScene>(loaded->scene.geometry);
  loaded->build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

}  // namespace app
