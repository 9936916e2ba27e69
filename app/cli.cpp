#include "app/cli.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "app/bench/bench.h"
#include "app/export_command.h"
#include "app/render_command.h"
#include "app/settings.h"
#include "app/view_command.h"

namespace app {
namespace {

// Registers every setting of the table as a string flag; apply_setting_flags validates them
// after parsing so that every bad value gets the same one-line message.
struct SettingFlags {
  std::map<std::string, std::string> text;
  std::map<std::string, CLI::Option*> options;
};

void add_setting_flags(CLI::App& command, SettingFlags& flags) {
  for (const SettingSpec& spec : setting_table()) {
    flags.options[spec.name] = command.add_option(std::string("--") + spec.name, flags.text[spec.name], spec.help);
  }
}

Settings apply_setting_flags(const SettingFlags& flags, CLI::Option* lights_option, const std::string& lights_text) {
  Settings settings;
  for (const SettingSpec& spec : setting_table()) {
    if (flags.options.at(spec.name)->count() > 0) set_setting(settings, spec, flags.text.at(spec.name));
  }
  if (flags.options.at("level")->count() > 0 && is_scene_file(settings)) {
    throw UsageError("--level: a scene file has no levels, got '" + flags.text.at("level") + "'");
  }
  if (lights_option->count() > 0) {
    if (flags.options.at("level")->count() > 0) throw UsageError("--lights: give --level or --lights, not both");
    char* end = nullptr;
    const unsigned long long n = std::strtoull(lights_text.c_str(), &end, 10);
    if (lights_text.empty() || *end != '\0' || lights_text[0] == '-') {
      throw UsageError("--lights: must be a light count of the scene, got '" + lights_text + "'");
    }
    apply_light_count(settings, n);
  }
  return settings;
}

int run_snapshot() {
  // The main job without a window: a snapshot of the default scene into out/.
  std::filesystem::create_directories("out");
  Settings settings;
  RenderOutputs outputs;
  outputs.image = "out/building.png";
  outputs.heatmap_lights = "out/building_lights_tested.png";
  outputs.heatmap_nodes = "out/building_nodes_visited.png";
  outputs.stats = "out/building_stats.json";
  outputs.reference_rt = true;
  const int code = run_render(settings, outputs);
  std::printf("wrote out/building.png, out/building_lights_tested.png, out/building_nodes_visited.png, "
              "out/building_stats.json\n");
  return code;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App cli{"levrt: ray tracing scenes with many lights through Light Extent Volumes"};
  cli.require_subcommand(0, 1);

  CLI::App* render = cli.add_subcommand("render", "render a scene headless: image, heatmaps, stats");
  SettingFlags render_flags;
  add_setting_flags(*render, render_flags);
  std::string lights_text;
  CLI::Option* lights_option =
      render->add_option("--lights", lights_text, "light count (selects the level with that many lights)");
  RenderOutputs outputs;
  const std::vector<CLI::Option*> output_options = {
      render->add_option("--out", outputs.image, "image PNG"),
      render->add_option("--heatmap-lights", outputs.heatmap_lights, "lights-tested heatmap PNG"),
      render->add_option("--heatmap-nodes", outputs.heatmap_nodes, "nodes-visited heatmap PNG"),
      render->add_option("--stats", outputs.stats, "statistics JSON")};
  std::string reference;
  CLI::Option* reference_option =
      render->add_option("--reference", reference, "also render this method's image and report pixel errors (rt)");

  CLI::App* export_command = cli.add_subcommand("export", "write a scene model's level (or a scene file) as a scene file");
  ExportFlags export_flags;
  add_export_flags(*export_command, export_flags);

  CLI::App* bench = cli.add_subcommand("bench", "the thesis' experiments: results.md, CSVs and plots");
  BenchFlags bench_flags;
  add_bench_flags(*bench, bench_flags);

  CLI::App* snapshot = cli.add_subcommand("snapshot", "the default job headless: building snapshot into out/");

  CLI::App* view = cli.add_subcommand("view", "the interactive viewer (the default when a display is available)");
  SettingFlags view_flags;
  add_setting_flags(*view, view_flags);
  std::string view_lights_text;
  CLI::Option* view_lights_option =
      view->add_option("--lights", view_lights_text, "light count (selects the level with that many lights)");
  ViewFlags view_options;
  add_view_flags(*view, view_options);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }

  if (render->parsed()) {
    const Settings settings = apply_setting_flags(render_flags, lights_option, lights_text);
    for (const CLI::Option* option : output_options) {
      if (option->count() > 0 && option->as<std::string>().empty()) {
        throw UsageError(option->get_name() + ": needs a file name, got ''");
      }
    }
    if (reference_option->count() > 0) {
      if (reference != "rt") throw UsageError("--reference: must be rt, got '" + reference + "'");
      outputs.reference_rt = true;
    }
    return run_render(settings, outputs);
  }
  if (export_command->parsed()) return run_export(export_flags);
  if (bench->parsed()) return run_bench(bench_flags);
  if (snapshot->parsed()) return run_snapshot();
  if (view->parsed()) {
    Settings settings = apply_setting_flags(view_flags, view_lights_option, view_lights_text);
    if (view_flags.options.at("spp")->count() == 0) settings.spp = kViewerDefaultPasses;
    return run_view(settings, view_options);
  }
  if (viewer_display_available()) {
    Settings settings;
    settings.spp = kViewerDefaultPasses;
    try {
      return run_view(settings, ViewFlags{});
    } catch (const NoDisplayError&) {
      // The display DISPLAY names cannot be opened: the headless job instead.
    }
  }
  return run_snapshot();
}

}  // namespace app
