// Turns the scene choice (scenes/scene_choice.h) into a renderable scene: the model's level (or
// the level with a requested light count) or a scene file, its Embree scene, and how long
// building them took.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/settings.h"
#include "renderer/ray_scene.h"
#include "renderer/scene.h"
#include "scenes/scene_description.h"

namespace app {

struct LoadedScene {
  renderer::Scene scene;
  std::unique_ptr<renderer::RayScene> rays;
  double build_seconds = 0.0;  // scene model, light hierarchy and Embree build
};

// True when --scene names a scene file (FILE.json) rather than a model.
bool is_scene_file(const scenes::SceneChoice& choice);

// Resolves --lights into choice.level; throws UsageError listing the valid counts.
void apply_light_count(scenes::SceneChoice& choice, std::uint64_t lights);
// The --lights flag's text: decimal digits only, reported as typed when it is refused.
void apply_light_count_flag(scenes::SceneChoice& choice, const std::string& text);

// Every file the choice reads: the scene file with what it refers to (a glTF's buffers and
// images) and --camera-from's stats file. No output may replace one of them.
std::vector<std::string> settings_input_files(const scenes::SceneChoice& choice);

// Throws UsageError ("--level: hall has levels 3..8, got '10'") for a model level the model lacks;
// a scene file has no levels to check.
void check_scene_level(const scenes::SceneChoice& choice);

// The description --scene names: a model's level, or a scene file read and validated (throws
// std::invalid_argument "FILE: /json/path: problem" for a bad file).
scenes::SceneDescription describe_scene(const scenes::SceneChoice& choice);

// Reads (or describes), instantiates and builds the scene. cancel (may be null) is polled
// between the steps; once it is raised the load throws LoadCancelled.
struct LoadCancelled : std::runtime_error {
  LoadCancelled() : std::runtime_error("the scene load was cancelled") {}
};
std::unique_ptr<LoadedScene> load_scene(const scenes::SceneChoice& choice,
                                        const std::atomic<bool>* cancel = nullptr);
// load_scene for a command under an InterruptScope (render, inspect), cancel its flag: a load
// that a signal cancelled, or a read the signal broke off (EINTR), throws the interrupt
// (InterruptScope::throw_if_interrupted), not the file's error.
std::unique_ptr<LoadedScene> load_scene_or_interrupt(const scenes::SceneChoice& choice,
                                                     const std::atomic<bool>* cancel);

}  // namespace app
