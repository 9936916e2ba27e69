// `levrt render`: render a scene headless with one method and write the image, the heatmaps and
// the statistics (DESIGN.md metric names), optionally against an `rt` reference.
#pragma once

#include <atomic>
#include <string>

#include <nlohmann/json.hpp>

#include "app/scene_loading.h"
#include "app/settings.h"
#include "renderer/framebuffer.h"

namespace app {

struct RenderOutputs {
  std::string image;           // PNG
  std::string heatmap_lights;  // PNG
  std::string heatmap_nodes;   // PNG
  std::string stats;           // JSON
  bool reference_rt = false;
};

// Throws UsageError for unusable paths: empty, a folder, a missing or unwritable folder, or two
// outputs naming the same file.
void check_output_paths(const RenderOutputs& outputs);

struct RenderResult {
  renderer::Framebuffer framebuffer;
  double seconds = 0.0;
  std::size_t method_bytes = 0;  // the method's own bookkeeping (AST)
};

// Renders settings.spp passes of `method` over the loaded scene. Throws Interrupted when
// *cancel is raised (Ctrl-C) before the last pass completes.
RenderResult render_image(LoadedScene& loaded, const Settings& settings, const std::string& method,
                          const std::atomic<bool>* cancel = nullptr);

// The stats JSON of a finished render (reference may be null).
nlohmann::ordered_json render_stats(const LoadedScene& loaded, const Settings& settings,
                                    const RenderResult& result, const RenderResult* reference);

int run_render(const Settings& settings, const RenderOutputs& outputs);

}  // namespace app
