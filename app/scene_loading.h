// Turns the scene settings into a renderable scene: the model's level (or the level with a
// requested light count), its Embree scene, and how long building them took.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "app/settings.h"
#include "renderer/ray_scene.h"
#include "renderer/scene.h"

namespace app {

struct LoadedScene {
  renderer::Scene scene;
  std::unique_ptr<renderer::RayScene> rays;
  double build_seconds = 0.0;  // scene model, light hierarchy and Embree build
};

// Resolves --lights into settings.level; throws UsageError listing the valid counts.
void apply_light_count(Settings& settings, std::uint64_t lights);

std::unique_ptr<LoadedScene> load_scene(const Settings& settings);

}  // namespace app
