// Turns the scene settings into a renderable scene: the model's level (or the level with a
// requested light count) or a scene file, its Embree scene, and how long building them took.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

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
bool is_scene_file(const Settings& settings);

// Resolves --lights into settings.level; throws UsageError listing the valid counts.
void apply_light_count(Settings& settings, std::uint64_t lights);
// The --lights flag's text: decimal digits only, reported as typed when it is refused.
void apply_light_count_flag(Settings& settings, const std::string& text);

// The description --scene names: a model's level, or a scene file read and validated (throws
// std::invalid_argument "FILE: /json/path: problem" for a bad file).
scenes::SceneDescription describe_scene(const Settings& settings);

std::unique_ptr<LoadedScene> load_scene(const Settings& settings);

}  // namespace app
