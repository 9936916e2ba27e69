#include "app/render_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <set>

#include <tbb/info.h>

#include "app/interrupt.h"
#include "lev/light_hierarchy.h"
#include "renderer/heatmap.h"
#include "renderer/image_io.h"
#include "renderer/pixel_error.h"
#include "renderer/render.h"

namespace app {
namespace fs = std::filesystem;

namespace {

void check_output_path(const char* flag, const std::string& path, std::set<std::string>& seen) {
  if (path.empty()) throw UsageError(std::string(flag) + ": needs a file name, got ''");
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw UsageError(std::string(flag) + ": is a folder, got '" + path + "'");
  const fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (!fs::is_directory(parent, ec)) {
    throw UsageError(std::string(flag) + ": folder does not exist, got '" + path + "'");
  }
  if (::access(parent.c_str(), W_OK) != 0) {
    throw UsageError(std::string(flag) + ": folder is not writable, got '" + path + "'");
  }
  const std::string key = fs::weakly_canonical(p, ec).string();
  if (!seen.insert(ec ? path : key).second) {
    throw UsageError(std::string(flag) + ": names a file another output also writes, got '" + path + "'");
  }
}

// Per-pixel mean of a counter over its samples, for the heatmaps.
std::vector<double> per_sample(const renderer::Framebuffer& fb, const std::vector<std::uint64_t>& counter) {
  std::vector<double> v(counter.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (fb.samples[i] > 0) v[i] = static_cast<double>(counter[i]) / fb.samples[i];
  }
  return v;
}

// The pixels a (possibly subsampled) render produced, as 8-bit RGB.
std::vector<std::uint8_t> rendered_pixels(const renderer::Framebuffer& fb) {
  const std::vector<std::uint8_t> all = renderer::framebuffer_rgb8(fb);
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < fb.samples.size(); ++i) {
    if (fb.samples[i] == 0) continue;
    out.insert(out.end(), all.begin() + static_cast<std::ptrdiff_t>(3 * i),
               all.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
  }
  return out;
}

}  // namespace

void check_output_paths(const RenderOutputs& o) {
  std::set<std::string> seen;
  const std::pair<const char*, const std::string*> outputs[] = {
      {"--out", &o.image}, {"--heatmap-lights", &o.heatmap_lights},
      {"--heatmap-nodes", &o.heatmap_nodes}, {"--stats", &o.stats}};
  for (const auto& [flag, path] : outputs) {
    if (path != nullptr && !path->empty()) check_output_path(flag, *path, seen);
  }
}

RenderResult render_image(LoadedScene& loaded, const Settings& settings, const std::string& method,
                          const std::atomic<bool>* cancel) {
  Settings s = settings;
  s.method = method;
  renderer::RenderStatePtr state =
      renderer::make_render_state(loaded.scene, *loaded.rays, render_settings_from(s));
  for (int pass = 0; pass < settings.spp; ++pass) {
    if (!renderer::render_pass(*state, cancel)) throw Interrupted();
  }
  RenderResult result;
  result.framebuffer = renderer::render_framebuffer(*state);
  result.seconds = renderer::render_seconds(*state);
  result.method_bytes = renderer::render_selector(*state).bookkeeping_bytes();
  return result;
}

nlohmann::ordered_json render_stats(const LoadedScene& loaded, const Settings& settings,
                                    const RenderResult& result, const RenderResult* reference) {
  const renderer::FramebufferTotals t = renderer::sum_framebuffer(result.framebuffer);
  const double points = t.shading_points > 0 ? static_cast<double>(t.shading_points) : 1.0;
  nlohmann::ordered_json j;
  j["scene"] = loaded.scene.name;
  j["level"] = loaded.scene.level;
  j["lights"] = loaded.scene.lights.light_count;
  j["method"] = settings.method;
  j["tolerance"] = settings.tolerance;
  j["width"] = settings.width;
  j["height"] = settings.height;
  j["spp"] = settings.spp;
  j["threads"] = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
  j["subsample"] = settings.subsample;
  j["time_build_s"] = loaded.build_seconds;
  j["time_render_s"] = result.seconds;
  j["shading_points"] = t.shading_points;
  j["shadow_rays"] = t.shadow_rays;
  j["lights_tested_avg"] = static_cast<double>(t.lights_tested) / points;
  j["lights_tested_max"] = t.lights_tested_max;
  j["nodes_visited_avg"] = static_cast<double>(t.nodes_visited) / points;
  j["hierarchy_bytes"] = lev::hierarchy_bytes(loaded.scene.lights);
  j["method_bytes"] = result.method_bytes;
  if (reference) {
    const auto error = renderer::summarize_pixel_error(renderer::pixel_error_pct(
        rendered_pixels(result.framebuffer), rendered_pixels(reference->framebuffer)));
    j["pixel_error_avg_pct"] = error.average_pct;
    j["pixel_error_max_pct"] = error.max_pct;
    j["time_reference_s"] = reference->seconds;
  }
  return j;
}

int run_render(const Settings& settings, const RenderOutputs& outputs) {
  render_settings_from(settings);  // validates the combination of settings before any work
  check_output_paths(outputs);
  const InterruptScope interrupt_scope;
  const std::atomic<bool>* cancel = &InterruptScope::flag();
  std::unique_ptr<LoadedScene> loaded = load_scene(settings);
  InterruptScope::throw_if_interrupted();
  const RenderResult result = render_image(*loaded, settings, settings.method, cancel);
  RenderResult reference;
  if (outputs.reference_rt) {
    reference = settings.method == "rt" ? result : render_image(*loaded, settings, "rt", cancel);
  }
  nlohmann::ordered_json stats =
      render_stats(*loaded, settings, result, outputs.reference_rt ? &reference : nullptr);

  InterruptScope::throw_if_interrupted();  // from here on every output is written in full
  const renderer::Framebuffer& fb = result.framebuffer;
  if (!outputs.image.empty()) {
    renderer::write_png_rgb8(outputs.image, fb.width, fb.height, renderer::framebuffer_rgb8(fb));
  }
  const std::pair<const std::string*, const std::vector<std::uint64_t>*> heatmaps[] = {
      {&outputs.heatmap_lights, &fb.lights_tested}, {&outputs.heatmap_nodes, &fb.nodes_visited}};
  const char* range_keys[] = {"heatmap_lights_range", "heatmap_nodes_range"};
  for (int k = 0; k < 2; ++k) {
    renderer::HeatmapRange range;
    const std::vector<std::uint8_t> rgb = renderer::heatmap_rgb8(per_sample(fb, *heatmaps[k].second), range);
    stats[range_keys[k]] = {range.min, range.max};
    if (!heatmaps[k].first->empty()) renderer::write_png_rgb8(*heatmaps[k].first, fb.width, fb.height, rgb);
  }
  stats["heatmap_scale"] = "log(1 + value per sample), viridis";
  if (!outputs.stats.empty()) renderer::write_text_file(outputs.stats, stats.dump(2) + "\n");

  std::printf("%s level %d, %llu lights, %s, tolerance %g: %.3f s render, %.2f lights tested/point, "
              "%.2f nodes visited/point",
              loaded->scene.name.c_str(), loaded->scene.level,
              static_cast<unsigned long long>(loaded->scene.lights.light_count), settings.method.c_str(),
              settings.tolerance, result.seconds, stats["lights_tested_avg"].get<double>(),
              stats["nodes_visited_avg"].get<double>());
  if (outputs.reference_rt) {
    std::printf(", pixel error avg %.4f%% max %.4f%%", stats["pixel_error_avg_pct"].get<double>(),
                stats["pixel_error_max_pct"].get<double>());
  }
  std::printf("\n");
  return 0;
}

}  // namespace app
