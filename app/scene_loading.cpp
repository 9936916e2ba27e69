#include "app/scene_loading.h"

#include <cerrno>
#include <cstdlib>
#include <string>

#include <chrono>

#include "app/camera_flags.h"
#include "app/interrupt.h"
#include "scenes/scene_file.h"
#include "scenes/scene_inputs.h"
#include "scenes/scene_instantiation.h"
#include "scenes/scene_models.h"

namespace app {
namespace {

const scenes::SceneModel& model_for(const scenes::SceneChoice& choice) {
  const scenes::SceneModel* model = scenes::find_scene_model(choice.name);
  if (!model) {
    throw UsageError("--scene: must be one of " + scenes::scene_model_names("|") + ", got '" +
                     choice.name + "'");
  }
  return *model;
}

}  // namespace

bool is_scene_file(const scenes::SceneChoice& choice) {
  return scenes::is_scene_file_name(choice.name);
}

namespace {

// `typed` is the count as the user gave it, so the message repeats it exactly.
void apply_light_count_typed(scenes::SceneChoice& choice, std::uint64_t lights,
                             const std::string& typed) {
  if (is_scene_file(choice)) {
    throw UsageError("--lights: a scene file has the lights it describes, got '" + typed + "'");
  }
  const scenes::SceneModel& model = model_for(choice);
  const int level = scenes::level_for_light_count(model, lights);
  if (level < 0) {
    throw UsageError("--lights: " + std::string(model.name) + " has " +
                     scenes::light_counts_text(model) + " lights, got '" + typed + "'");
  }
  choice.level = level;
}

}  // namespace

void apply_light_count(scenes::SceneChoice& choice, std::uint64_t lights) {
  apply_light_count_typed(choice, lights, std::to_string(lights));
}

void apply_light_count_flag(scenes::SceneChoice& choice, const std::string& text) {
  // Digits only: strtoull would take " -1" as 2^64 - 1 and clamp a 20-digit count to it.
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  std::uint64_t lights = 0;
  if (digits) {
    errno = 0;
    lights = std::strtoull(text.c_str(), nullptr, 10);
  }
  if (!digits || errno == ERANGE) {
    throw UsageError("--lights: must be a light count of the scene, got '" + text + "'");
  }
  apply_light_count_typed(choice, lights, text);
}

void check_scene_level(const scenes::SceneChoice& choice) {
  if (is_scene_file(choice)) return;
  const scenes::SceneModel& model = model_for(choice);
  if (choice.level < model.min_level || choice.level > model.max_level) {
    throw UsageError("--level: " + std::string(model.name) + " has levels " +
                     std::to_string(model.min_level) + ".." + std::to_string(model.max_level) +
                     ", got '" + std::to_string(choice.level) + "'");
  }
}

scenes::SceneDescription describe_scene(const scenes::SceneChoice& choice) {
  if (is_scene_file(choice)) {
    return scenes::load_scene_file(choice.name, {choice.camera});
  }
  check_scene_level(choice);
  return model_for(choice).describe(choice.level);
}

std::vector<std::string> settings_input_files(const scenes::SceneChoice& choice) {
  std::vector<std::string> files = scenes::scene_input_files(choice.name);
  if (!choice.camera_flags.from_file.empty()) files.push_back(choice.camera_flags.from_file);
  return files;
}

std::unique_ptr<LoadedScene> load_scene(const scenes::SceneChoice& choice,
                                        const std::atomic<bool>* cancel) {
  const auto poll = [cancel] {
    if (cancel && cancel->load()) throw LoadCancelled();
  };
  const auto start = std::chrono::steady_clock::now();
  // The steps the interrupted line names (app/interrupt.h).
  CommandStage stage({"loading the scene", "step", 1, 3,
                      is_scene_file(choice) ? "reading the scene file" : "describing the model"});
  poll();
  const scenes::SceneDescription description = describe_scene(choice);
  poll();
  stage.step(2, "instantiating its lights and geometry");
  auto loaded = std::make_unique<LoadedScene>();
  loaded->scene = scenes::instantiate_scene(description);
  loaded->scene.camera =
      apply_camera_flags(loaded->scene.camera, choice.camera_flags, loaded->scene.world_origin);
  poll();
  stage.step(3, "building its ray-tracing structures");
  loaded->rays = std::make_unique<renderer::RayScene>(loaded->scene);
  poll();
  loaded->build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

std::unique_ptr<LoadedScene> load_scene_or_interrupt(const scenes::SceneChoice& choice,
                                                     const std::atomic<bool>* cancel) {
  try {
    return load_scene(choice, cancel);
  } catch (...) {
    InterruptScope::throw_if_interrupted();
    throw;
  }
}

}  // namespace app
