#include "app/render_command.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>

#include "app/camera_flags.h"
#include "app/exr_encoding.h"
#include "app/interrupt.h"
#include "app/json_text.h"
#include "app/output_files.h"
#include "app/render_stats.h"
#include "lev/light_hierarchy.h"
#include "renderer/auto_exposure.h"
#include "renderer/display_transform.h"
#include "renderer/error_bound.h"
#include "renderer/heatmap.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_error.h"
#include "renderer/pixel_noise.h"
#include "scenes/scene_file.h"
#include "scenes/scene_inputs.h"

namespace app {
namespace fs = std::filesystem;

namespace {

// Per-pixel mean of a counter over its samples, for the heatmaps.
std::vector<double> per_sample(const renderer::Framebuffer& fb,
                               const std::vector<std::uint64_t>& counter) {
  std::vector<double> v(counter.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (fb.samples[i] > 0) v[i] = static_cast<double>(counter[i]) / fb.samples[i];
  }
  return v;
}

// The heatmap file asked for the view; empty when none is.
std::string heatmap_path(const RenderOutputs& o, ViewMode view) {
  const auto path = o.heatmaps.find(view);
  return path == o.heatmaps.end() ? std::string() : path->second;
}

}  // namespace

std::vector<ExrChannel> framebuffer_exr_channels(const renderer::Framebuffer& fb,
                                                 const std::vector<double>& error_pct) {
  std::vector<glm::vec3> radiance(fb.radiance_sum.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < radiance.size(); ++i) {
    if (fb.samples[i] > 0) radiance[i] = fb.radiance_sum[i] / static_cast<float>(fb.samples[i]);
  }
  std::vector<ExrChannel> channels = rgb_channels(radiance);
  const auto add = [&channels](const char* name, const std::vector<double>& values) {
    channels.push_back({name, std::vector<float>(values.begin(), values.end())});
  };
  add("samples", std::vector<double>(fb.samples.begin(), fb.samples.end()));
  add("lights_tested", per_sample(fb, fb.lights_tested));
  add("nodes_visited", per_sample(fb, fb.nodes_visited));
  add("error_bound_pct", renderer::error_bound_pct_image(fb));
  add("noise_pct", renderer::pixel_std_error_pct(fb));
  if (!fb.missed_sum.empty()) add("missed_pct", renderer::missed_pct_image(fb));
  if (!error_pct.empty()) add("error_pct", error_pct);
  return channels;
}

renderer::HeatmapRange parse_heatmap_range(const std::string& text) {
  const std::size_t comma = text.find(',');
  const auto number = [&](const std::string& part, double& v) {
    if (!is_decimal_real(part)) return false;
    char* end = nullptr;
    v = std::strtod(part.c_str(), &end);
    // Overflow is infinite and refused; underflow (ERANGE, a subnormal or zero) is the typed value
    // rounded, as the settings take it.
    return *end == '\0' && std::isfinite(v);
  };
  renderer::HeatmapRange range;
  if (comma == std::string::npos || !number(text.substr(0, comma), range.min) ||
      !number(text.substr(comma + 1), range.max) || range.min < 0.0 || !(range.max > range.min)) {
    throw UsageError("--heatmap-range: must be LO,HI with 0 <= LO < HI, got '" + text + "'");
  }
  return range;
}

std::vector<OutputPath> render_output_paths(const RenderOutputs& o) {
  std::vector<OutputPath> paths = {{"--out", o.image, ".png|.exr", "PNG or EXR"},
                                   {"--stats", o.stats, ".json", "JSON"}};
  for (const ViewInfo& view : view_table()) {
    if (*view.output_flag != '\0')
      paths.push_back({view.output_flag, heatmap_path(o, view.mode), ".png", "PNG"});
  }
  paths.push_back({"--reference-out", o.reference_image, ".png|.exr", "PNG or EXR"});
  return paths;
}

std::string memory_budget_refusal(const Settings& settings, bool reference,
                                  std::uint64_t budget_bytes) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(settings.image.width) *
                               static_cast<std::uint64_t>(settings.image.height);
  const std::uint64_t per_pixel = reference ? kReferenceRenderBytesPerPixel : kRenderBytesPerPixel;
  if (pixels * per_pixel <= budget_bytes) return std::string();
  return "--width/--height: " + std::to_string(settings.image.width) + "x" +
         std::to_string(settings.image.height) + (reference ? " with --reference" : "") +
         " needs about " + std::to_string((pixels * per_pixel) >> 20) + " MiB (" +
         std::to_string(per_pixel) + " bytes per pixel, subsampled or not), more than the " +
         std::to_string(budget_bytes >> 20) + " MiB budget";
}

void check_memory_budget(const Settings& settings, bool reference) {
  const std::string refusal = memory_budget_refusal(settings, reference);
  if (!refusal.empty()) throw UsageError(refusal);
}

renderer::RenderResult render_image(const LoadedScene& loaded, const Settings& settings,
                                    lev::Method method, const std::atomic<bool>* cancel,
                                    bool show_progress) {
  Settings s = settings;
  s.method.method = method;
  bool progress_shown = false;
  const auto on_pass_done = [&](int passes_done, double elapsed_s) {
    if (show_progress && elapsed_s >= 1.0 && passes_done < settings.image.spp) {
      const double left_s = elapsed_s / passes_done * (settings.image.spp - passes_done);
      std::fprintf(stderr, "\rlevrt: %s pass %d/%d, about %.0f s left   ",
                   lev::method_info(method).name, passes_done, settings.image.spp, left_s);
      progress_shown = true;
    }
  };
  renderer::RenderSettings render_settings = render_settings_from(s);
  render_settings.compute_error_bound = true;  // every render reports its certified bound
  // The pass and its tiles done are what the interrupted line reports (app/interrupt.h).
  CommandStage stage({std::string("rendering ") + lev::method_info(method).name, "pass", 1,
                      settings.image.spp, "setting up the method"});
  renderer::PassHooks hooks;
  hooks.on_ready = [&](const renderer::RenderState& state) {
    stage.count_tiles(renderer::render_tile_count(state));
  };
  hooks.on_pass_start = [&](int pass) { stage.step(pass); };
  hooks.on_tile_done = [](int) { note_tile_done(); };
  hooks.on_pass_done = on_pass_done;
  renderer::RenderResult result;
  const bool done = renderer::render_passes(loaded.scene, *loaded.rays, render_settings,
                                            settings.image.spp, result, cancel, hooks);
  if (progress_shown) std::fprintf(stderr, done ? "\r\033[K" : "\n");
  if (!done) throw Interrupted();
  return result;
}

namespace {

// The statistics of a finished render (reference may be null); the heatmap ranges are filled by
// the caller, which draws the heatmaps.
RenderStats render_stats(const LoadedScene& loaded, const Settings& settings,
                         const renderer::RenderResult& result,
                         const renderer::RenderResult* reference) {
  RenderStats s;
  s.scene = loaded.scene.name;
  s.level = loaded.scene.level;
  s.lights = loaded.scene.lights.light_count;
  s.method = lev::method_info(settings.method.method).name;
  s.tolerance = settings.method.tolerance;
  s.width = settings.image.width;
  s.height = settings.image.height;
  s.spp = result.passes;
  set_stats_from_settings(s, settings);
  s.build_seconds = loaded.build_seconds;
  s.setup_seconds = result.setup_seconds;
  s.render_seconds = result.render_seconds;
  s.pass_seconds = result.passes > 0 ? result.render_seconds / result.passes : 0.0;
  s.totals = result.totals;
  s.rendered_pixels = result.rendered_pixels;
  s.hierarchy_bytes = lev::hierarchy_bytes(loaded.scene.lights);
  s.method_bytes = result.method_bytes;
  s.rt_fallback = result.rt_fallback;
  s.camera = world_camera(loaded.scene.camera, loaded.scene.world_origin);
  s.directional_lights = loaded.scene.directional_lights.size();
  s.error_bound = renderer::error_bound_stats(result.totals);
  if (result.passes >= 2) s.std_error_avg_pct = renderer::std_error_avg_pct(result.framebuffer);
  if (settings.image.missed_draws > 0) {
    s.missed = renderer::missed_light_stats(result.framebuffer);
    s.missed_draws = settings.image.missed_draws;
  }
  if (reference) {
    const auto error = renderer::summarize_pixel_error(
        renderer::pixel_error_pct(result.rendered_rgb, reference->rendered_rgb));
    s.error = RenderPixelError{error.average_pct, error.max_pct, result.rendered_pixels,
                               "every pass against the rt reference's, the rendered pixels",
                               reference->render_seconds};
  }
  return s;
}

// The summary line (stdout, or stderr when standard output carries an output) and the line naming
// every file written.
void print_render_summary(const LoadedScene& loaded, const Settings& settings,
                          const RenderOutputs& outputs, const renderer::RenderResult& result,
                          const RenderStats& stats, const nlohmann::ordered_json& json);

}  // namespace

int run_render(const Settings& typed_settings, const RenderOutputs& outputs) {
  Settings settings = typed_settings;
  const lev::MethodInfo& method = lev::method_info(settings.method.method);
  if (!heatmap_path(outputs, ViewMode::missed).empty() && !method.missed_light_known) {
    throw UsageError("--heatmap-missed: method " + std::string(method.name) +
                     " does not estimate the light it leaves out (the heatmap would read 0 where "
                     "its pixels differ from rt's), got '" +
                     heatmap_path(outputs, ViewMode::missed) + "'");
  }
  if (!heatmap_path(outputs, ViewMode::missed).empty() && settings.image.missed_draws == 0) {
    settings.image.missed_draws = kDefaultMissedDraws;
  }
  render_settings_from(settings);  // validates the combination of settings before any work
  if (!outputs.reference_rt) {
    const std::string rt = lev::method_info(lev::reference_method()).name;
    for (const ViewInfo& view : view_table()) {
      if (view.needs_reference && !heatmap_path(outputs, view.mode).empty())
        throw UsageError(std::string(view.output_flag) + ": needs --reference " + rt);
    }
    if (!outputs.reference_image.empty())
      throw UsageError("--reference-out: needs --reference " + rt);
    if (outputs.fail_above) throw UsageError("--fail-above: needs --reference " + rt);
  }
  check_memory_budget(settings, outputs.reference_rt);
  check_output_paths(render_output_paths(outputs), settings_input_files(settings.scene));
  // The noise is the spread across passes: one pass has none to show (the stats say null).
  if (!heatmap_path(outputs, ViewMode::noise).empty() && settings.image.spp < 2) {
    throw UsageError(
        "--heatmap-noise: the noise is the spread across passes and needs --spp 2 or "
        "more (--spp " +
        std::to_string(settings.image.spp) + " would draw it blank), got '" +
        heatmap_path(outputs, ViewMode::noise) + "'");
  }
  const InterruptScope interrupt_scope;
  const std::atomic<bool>* cancel = &InterruptScope::flag();
  // Until the outputs are written nothing is, so Ctrl-C may end the process outright.
  std::optional<InterruptWatchdog> watchdog(std::in_place);
  std::unique_ptr<LoadedScene> loaded = load_scene_or_interrupt(settings.scene, cancel);
  if (settings.display.exposure_auto) {
    const CommandStage stage("choosing the exposure");
    settings.display.exposure_ev =
        renderer::auto_exposure_ev(loaded->scene, *loaded->rays, render_settings_from(settings),
                                   settings.display.curve, cancel);
    InterruptScope::throw_if_interrupted();
  }
  const bool show_progress = !outputs.quiet && ::isatty(STDERR_FILENO) == 1;
  const renderer::RenderResult result =
      render_image(*loaded, settings, settings.method.method, cancel, show_progress);
  renderer::RenderResult reference;
  if (outputs.reference_rt) {
    const lev::Method rt = lev::reference_method();
    reference = settings.method.method == rt
                    ? result
                    : render_image(*loaded, settings, rt, cancel, show_progress);
  }
  const CommandStage rendered("finishing after the last pass");
  RenderStats stats =
      render_stats(*loaded, settings, result, outputs.reference_rt ? &reference : nullptr);

  watchdog.reset();
  InterruptScope::throw_if_interrupted();  // from here on every output is written in full
  const renderer::Framebuffer& fb = result.framebuffer;
  std::vector<std::uint8_t> reference_rgb;
  std::vector<double> error_pct;
  if (outputs.reference_rt) {
    reference_rgb =
        renderer::display_framebuffer_rgb8(reference.framebuffer, display_from(settings));
    error_pct = renderer::pixel_error_pct(renderer::framebuffer_rgb8(fb),
                                          renderer::framebuffer_rgb8(reference.framebuffer));
  }
  // Every heatmap the view table gives a flag, from the fields this render has; their ranges go
  // into the statistics, so each is drawn before the statistics are encoded, and only the pixels
  // of those asked for are kept.
  const std::vector<double> lights = per_sample(fb, fb.lights_tested);
  const std::vector<double> nodes = per_sample(fb, fb.nodes_visited);
  const std::vector<double> bound = renderer::error_bound_pct_image(fb);
  const std::vector<double> noise = renderer::pixel_std_error_pct(fb);
  std::vector<double> missed;
  if (stats.missed) missed = renderer::missed_pct_image(fb);
  ViewPixels pixels;
  pixels.count = fb.samples.size();
  pixels.samples = fb.samples.data();
  pixels.lights_tested = lights.data();
  pixels.nodes_visited = nodes.data();
  pixels.error_bound_pct = bound.data();
  pixels.noise_pct = noise.data();
  if (stats.missed) pixels.missed_pct = missed.data();
  if (outputs.reference_rt) pixels.error_pct = error_pct.data();
  std::map<ViewMode, std::vector<std::uint8_t>> heatmap_rgb;
  for (const ViewInfo& view : view_table()) {
    if (*view.output_flag == '\0' || (view.needs_reference && !outputs.reference_rt) ||
        (view.needs_missed && !stats.missed)) {
      continue;
    }
    renderer::HeatmapRange& range = stats.heatmap_ranges[view.mode];
    if (outputs.heatmap_range) range = *outputs.heatmap_range;
    std::vector<std::uint8_t> rgb =
        renderer::heatmap_rgb8(view_values(view, pixels), range, outputs.heatmap_range.has_value());
    if (!heatmap_path(outputs, view.mode).empty()) heatmap_rgb[view.mode] = std::move(rgb);
  }
  const nlohmann::ordered_json json = render_stats_json(stats);
  std::vector<OutputFile> files;
  const auto add = [&files](const std::string& path, std::function<std::string()> bytes) {
    if (!path.empty()) files.push_back({path, std::move(bytes)});
  };
  add(outputs.image, [&fb, &settings, &outputs, &error_pct] {
    if (is_exr_path(outputs.image))
      return exr_bytes(fb.width, fb.height, framebuffer_exr_channels(fb, error_pct));
    return png_rgb8_bytes(fb.width, fb.height,
                          renderer::display_framebuffer_rgb8(fb, display_from(settings)));
  });
  const auto png_of = [&fb](const std::vector<std::uint8_t>& rgb) {
    return [&fb, &rgb] { return png_rgb8_bytes(fb.width, fb.height, rgb); };
  };
  for (const auto& [view, rgb] : heatmap_rgb) add(heatmap_path(outputs, view), png_of(rgb));
  add(outputs.reference_image, [&reference, &reference_rgb, &outputs, &fb] {
    if (is_exr_path(outputs.reference_image)) {
      const renderer::Framebuffer& rf = reference.framebuffer;
      return exr_bytes(rf.width, rf.height, framebuffer_exr_channels(rf, {}));
    }
    return png_rgb8_bytes(fb.width, fb.height, reference_rgb);
  });
  add(outputs.stats, [&json] { return json_text(json, 2); });
  write_output_files(files);

  const std::optional<std::string> gate_failure =
      outputs.fail_above && stats.error
          ? accuracy_gate_failure(*outputs.fail_above,
                                  {stats.error->average_pct, stats.error->max_pct})
          : std::nullopt;
  if (!outputs.quiet) print_render_summary(*loaded, settings, outputs, result, stats, json);
  if (gate_failure) {
    std::fprintf(stderr, "levrt: %s\n", gate_failure->c_str());
    return kAccuracyGateExitCode;
  }
  return 0;
}

namespace {

void print_render_summary(const LoadedScene& loaded, const Settings& settings,
                          const RenderOutputs& outputs, const renderer::RenderResult& result,
                          const RenderStats& stats, const nlohmann::ordered_json& json) {
  // Standard output may carry an output file ("-"): the summary then goes to stderr.
  std::FILE* summary = stdout;
  for (const OutputPath& output : render_output_paths(outputs)) {
    if (output.path == app::kStandardOutputName) summary = stderr;
  }
  const std::string method_text = method_settings_text(settings);
  std::fprintf(summary,
               "%s level %d, %llu lights, %s: %.3f s render, %.2f lights tested/point, "
               "%.2f nodes visited/point",
               scenes::escape_control_characters(loaded.scene.name).c_str(), loaded.scene.level,
               static_cast<unsigned long long>(loaded.scene.lights.light_count),
               method_text.c_str(), result.render_seconds, json["lights_tested_avg"].get<double>(),
               json["nodes_visited_avg"].get<double>());
  std::fprintf(summary, ", error bound avg %.4f%% max %.4f%%",
               json["error_bound_avg_pct"].get<double>(),
               json["error_bound_max_pct"].get<double>());
  if (outputs.reference_rt) {
    std::fprintf(summary, ", pixel error avg %.4f%% max %.4f%%",
                 json["pixel_error_avg_pct"].get<double>(),
                 json["pixel_error_max_pct"].get<double>());
  }
  if (stats.std_error_avg_pct)
    std::fprintf(summary, ", std error avg %.4f%%", *stats.std_error_avg_pct);
  if (stats.missed) {
    std::fprintf(summary, ", missed estimate avg %.4f%% (std error %.4f%%) max %.4f%%",
                 stats.missed->average_pct, stats.missed->std_error_avg_pct, stats.missed->max_pct);
  }
  std::fprintf(summary, "\n");
  std::string written;
  for (const OutputPath& output : render_output_paths(outputs)) {
    if (!output.path.empty()) {
      written +=
          (written.empty() ? "" : ", ") + (output.path == app::kStandardOutputName
                                               ? std::string("standard output")
                                               : scenes::escape_control_characters(output.path));
    }
  }
  if (!written.empty()) std::fprintf(stderr, "wrote %s\n", written.c_str());
}

}  // namespace

}  // namespace app
