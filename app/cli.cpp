#include "app/cli.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <variant>

#include <CLI/CLI.hpp>

#include "app/accuracy_gate.h"
#include "app/bench/bench.h"
#include "app/camera_flags.h"
#include "app/export_command.h"
#include "app/inspect_command.h"
#include "app/render_command.h"
#include "app/settings.h"
#include "app/view_command.h"
#include "scenes/scene_choice.h"
#include "scenes/scene_file.h"

namespace app {
namespace {

// Registers every setting of the table as a string flag; apply_setting_flags validates them
// after parsing so that every bad value gets the same one-line message.
struct SettingFlags {
  std::map<std::string, std::string> text;
  std::map<std::string, CLI::Option*> options;
};

// The allowed values of a setting as --help shows them, from the table's ranges and choices.
std::string setting_type_name(const SettingSpec& spec) {
  if (const auto* r = std::get_if<IntRange>(&spec.kind)) {
    return "INT in [" + std::to_string(r->min) + ", " + std::to_string(r->max) + "]";
  }
  if (const auto* d = std::get_if<RealRange>(&spec.kind)) {
    std::ostringstream text;
    text << "FLOAT";
    if (d->max == std::numeric_limits<double>::max()) {
      text << " >= " << d->min;
    } else {
      text << " in [" << d->min << ", " << d->max << "]";
    }
    if (d->word) text << "|" << d->word;
    return text.str();
  }
  const auto& c = std::get<Choice>(spec.kind);
  std::string valid;
  for (const std::string& o : c.options()) valid += (valid.empty() ? "" : "|") + o;
  return "{" + valid + "}" +
         (c.also_accepts_label ? std::string(" or ") + c.also_accepts_label : "");
}

// The help line of a setting; a choice whose options carry summaries (the method table) lists them.
std::string setting_help(const SettingSpec& spec) {
  std::string help = spec.help;
  const auto* c = std::get_if<Choice>(&spec.kind);
  if (!c || !c->option_summary) return help;
  for (const std::string& o : c->options()) help += "\n  " + o + ": " + c->option_summary(o);
  return help;
}

// defaults: what the command uses for a flag not given (the viewer renders more passes).
void add_setting_flags(CLI::App& command, SettingFlags& flags, const Settings& defaults) {
  for (const SettingSpec& spec : setting_table()) {
    flags.options[spec.name] =
        command
            .add_option(std::string("--") + spec.name, flags.text[spec.name], setting_help(spec))
            ->type_name(setting_type_name(spec))
            ->default_str(setting_text(defaults, spec));
  }
}

// A count in the settings' integer grammar (is_decimal_integer), in [0, INT_MAX]: checked on the
// text, before CLI11 converts it (which would take "0x10" and " 3", and say only "Could not
// convert" for "3.5" or 1e20).
const CLI::Validator& decimal_count() {
  static const CLI::Validator check(
      [](std::string& value) {
        const bool digits = is_decimal_integer(value) && value[0] != '-' && value.size() <= 10;
        if (digits && std::stoll(value) <= std::numeric_limits<int>::max()) return std::string();
        return "must be a decimal integer in [0, " +
               std::to_string(std::numeric_limits<int>::max()) + "], got '" + value + "'";
      },
      "", "decimal count");
  return check;
}

// The camera flags (app/camera_flags.h) of a command that renders a scene.
void add_camera_flags(CLI::App& command, CameraFlagTexts& texts) {
  command.add_option("--camera-position", texts.position, "the camera's position")
      ->type_name("X,Y,Z")
      ->check(non_empty_value());
  command.add_option("--camera-target", texts.target, "the point the camera looks at")
      ->type_name("X,Y,Z")
      ->check(non_empty_value());
  command.add_option("--camera-up", texts.up, "the camera's up direction")
      ->type_name("X,Y,Z")
      ->check(non_empty_value());
  command.add_option("--fov", texts.fov_deg, "vertical field of view, degrees in (0, 180)")
      ->type_name("DEG")
      ->check(non_empty_value());
  command
      .add_option("--ortho-half-height", texts.ortho_half_height,
                  "an orthographic view this many scene units above and below its axis")
      ->type_name("UNITS")
      ->check(non_empty_value());
  command
      .add_option("--camera-from", texts.from_file,
                  "the camera of a stats JSON levrt wrote (the flags above override its parts)")
      ->type_name("STATS.json")
      ->check(non_empty_value());
}

// `levrt NAME` where NAME is no command: CLI11 would call it an unexpected argument.
void check_subcommand_name(const CLI::App& cli, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string names;
  for (const CLI::App* sub : cli.get_subcommands({})) {
    if (sub->get_name() == argv[1]) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw UsageError("unknown command '" + std::string(argv[1]) + "'; the commands are " + names);
}

// A flag an older levrt had under another name: CLI11 would only say it was not expected.
void check_renamed_flags(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0) continue;
    const std::string name = arg.substr(2, arg.find('=') - 2);
    if (const char* now = renamed_setting(name))
      throw UsageError("--" + name + ": is now called --" + now + ", got '" + arg + "'");
  }
}

// CLI11 refuses a flag given twice as "--tolerance: At Most 1 required but received 2": said with
// the values given, each as typed, as every refusal names its value.
std::string repeated_flag_message(const std::string& what, int argc, char** argv) {
  const std::size_t colon = what.find(": At Most 1 required");
  if (colon == std::string::npos || what.rfind("--", 0) != 0) return what;
  const std::string flag = what.substr(0, colon);
  std::string values;
  int count = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string value;
    if (arg == flag && i + 1 < argc) {
      value = argv[++i];
    } else if (arg.rfind(flag + "=", 0) == 0) {
      value = arg.substr(flag.size() + 1);
    } else {
      continue;
    }
    values += std::string(count++ == 0 ? "" : ", then ") + "'" + value + "'";
  }
  if (count < 2) return what;
  return flag + ": may be given once, got " + values;
}

Settings apply_setting_flags(const SettingFlags& flags, const Settings& defaults,
                             CLI::Option* lights_option, const std::string& lights_text) {
  Settings settings = defaults;
  for (const SettingSpec& spec : setting_table()) {
    if (flags.options.at(spec.name)->count() > 0)
      set_setting(settings, spec, flags.text.at(spec.name));
  }
  // A typed size is what the user wants to see, in the viewer too.
  const bool size_typed =
      flags.options.at("width")->count() > 0 || flags.options.at("height")->count() > 0;
  if (size_typed && flags.options.at("resolution")->count() == 0) settings.resolution = "typed";
  if (flags.options.at("level")->count() > 0 && is_scene_file(settings.scene)) {
    throw UsageError("--level: a scene file has no levels, got '" + flags.text.at("level") + "'");
  }
  // A setting given for a scene or method that ignores it (the table's unused_because, which the
  // viewer greys) is refused, not ignored: --tolerance with rt, --lights-per-point with lev, ...
  for (const SettingSpec& spec : setting_table()) {
    if (flags.options.at(spec.name)->count() == 0 || !spec.unused_because) continue;
    if (const char* reason = spec.unused_because(settings)) {
      const std::string method = lev::method_info(settings.method.method).name;
      const std::string who =
          std::string(spec.name) == "camera" ? std::string() : "method " + method + " ignores it: ";
      throw UsageError("--" + std::string(spec.name) + ": " + who + reason + ", got '" +
                       flags.text.at(spec.name) + "'");
    }
  }
  apply_scene_display_defaults(settings, flags.options.at("exposure")->count() > 0,
                               flags.options.at("display")->count() > 0);
  if (lights_option->count() > 0) {
    if (flags.options.at("level")->count() > 0)
      throw UsageError("--lights: give --level or --lights, not both");
    apply_light_count_flag(settings.scene, lights_text);
  }
  return settings;
}

// Everything a command that renders a scene takes about it: the settings table, the light
// count and the camera.
struct SceneFlags {
  SettingFlags settings;
  CameraFlagTexts camera;
  std::string lights_text;
  CLI::Option* lights = nullptr;
};

void add_scene_flags(CLI::App& command, SceneFlags& flags, const Settings& defaults) {
  add_setting_flags(command, flags.settings, defaults);
  add_camera_flags(command, flags.camera);
  flags.lights = command
                     .add_option("--lights", flags.lights_text,
                                 "light count (selects the level with that many lights)")
                     ->type_name("COUNT");
}

Settings apply_scene_flags(const SceneFlags& flags, const Settings& defaults) {
  Settings settings =
      apply_setting_flags(flags.settings, defaults, flags.lights, flags.lights_text);
  settings.scene.camera_flags = parse_camera_flags(flags.camera);
  return settings;
}

// A headless command (render, inspect) sizes its image by --width and --height alone: the viewer's
// sizing rule is refused rather than ignored.
void refuse_viewer_only_flags(const SceneFlags& flags) {
  if (flags.settings.options.at("resolution")->count() > 0) {
    throw UsageError(
        "--resolution: only the viewer sizes its image by it (headless commands render "
        "--width x --height), got '" +
        flags.settings.text.at("resolution") + "'");
  }
}

// The inspector traces one pixel's pass-0 sample and lists its lights: it makes no missed-light
// estimate, so draws asked for it would change nothing (refused, as a flag the method ignores).
void refuse_inspect_ignored_flags(const SceneFlags& flags) {
  const std::string& draws = flags.settings.text.at("missed-draws");
  if (flags.settings.options.at("missed-draws")->count() > 0 && draws != "0") {
    throw UsageError(
        "--missed-draws: inspect makes no missed-light estimate (its lists give each culled "
        "light's loss; render --heatmap-missed estimates it), got '" +
        draws + "'");
  }
}

// A typed --width or --height selects --resolution typed; beside --resolution fit (or fit/2,
// fit/4), which sizes the image by the window, it was ignored without a word.
void refuse_size_beside_a_fitted_resolution(const SceneFlags& flags, const Settings& settings) {
  if (flags.settings.options.at("resolution")->count() == 0 || settings.resolution == "typed")
    return;
  for (const char* flag : {"width", "height"}) {
    if (flags.settings.options.at(flag)->count() == 0) continue;
    throw UsageError(std::string("--") + flag + ": --resolution " + settings.resolution +
                     " sizes the image by the window (give --resolution typed for a typed size), "
                     "got '" +
                     flags.settings.text.at(flag) + "'");
  }
}

int run_snapshot() {
  // The main job without a window: a snapshot of the default scene into out/. A name "out" that
  // is not a folder (a file, a dangling symlink) is the user's: refused, left as it is.
  std::error_code ec;
  std::filesystem::create_directories("out", ec);
  if (ec || !std::filesystem::is_directory("out")) {
    throw UsageError("snapshot: cannot make the folder 'out' for its files (" +
                     (ec ? ec.message() : std::string("not a folder")) + "), got '" +
                     (std::filesystem::current_path() / "out").string() + "'");
  }
  Settings settings;
  RenderOutputs outputs;
  outputs.image = "out/building.png";
  outputs.heatmaps[ViewMode::lights] = "out/building_lights_tested.png";
  outputs.heatmaps[ViewMode::nodes] = "out/building_nodes_visited.png";
  outputs.heatmaps[ViewMode::bound] = "out/building_error_bound.png";
  outputs.stats = "out/building_stats.json";
  outputs.reference_rt = true;
  return run_render(settings, outputs);
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App cli{"levrt: ray tracing scenes with many lights through Light Extent Volumes"};
  cli.require_subcommand(0, 1);

  CLI::App* render =
      cli.add_subcommand("render", "render a scene headless: image, heatmaps, stats");
  SceneFlags render_flags;
  add_scene_flags(*render, render_flags, Settings{});
  RenderOutputs outputs;
  std::vector<CLI::Option*> output_options = {
      render
          ->add_option("--out", outputs.image,
                       "image: PNG (displayed; - for standard output) or EXR (scene-linear "
                       "radiance as float, with the per-pixel counters and errors as channels)")
          ->type_name("FILE.png|FILE.exr"),
      render->add_option("--stats", outputs.stats, "statistics JSON")->type_name("FILE.json"),
      render
          ->add_option("--reference-out", outputs.reference_image,
                       "the reference's image, PNG or EXR (needs --reference)")
          ->type_name("FILE.png|FILE.exr")};
  // A heatmap flag for every view the table gives one (app/view_table.h).
  for (const ViewInfo& view : view_table()) {
    if (*view.output_flag == '\0') continue;
    output_options.push_back(
        render->add_option(view.output_flag, outputs.heatmaps[view.mode], view.output_help)
            ->type_name("FILE.png"));
  }
  std::string heatmap_range;
  CLI::Option* heatmap_range_option =
      render
          ->add_option("--heatmap-range", heatmap_range,
                       "draw every heatmap over LO..HI (log scale above LO) instead of its own "
                       "0..max, to compare renders on one scale")
          ->type_name("LO,HI");
  std::string fail_above;
  CLI::Option* fail_above_option =
      render
          ->add_option("--fail-above", fail_above,
                       "exit 3 when the pixel error against the reference exceeds either limit "
                       "(percent; needs "
                       "--reference)")
          ->type_name("avg=A,max=M");
  render->add_flag("--quiet", outputs.quiet, "no progress, summary or 'wrote' line");
  std::string reference;
  const std::string reference_name = lev::method_info(lev::reference_method()).name;
  CLI::Option* reference_option =
      render
          ->add_option(
              "--reference", reference,
              "also render this method's image and report pixel errors (" + reference_name + ")")
          ->type_name("{" + reference_name + "}");

  CLI::App* inspect = cli.add_subcommand(
      "inspect", "list the lights behind one pixel: tested, culled (by which node), clustered");
  SceneFlags inspect_flags;
  add_scene_flags(*inspect, inspect_flags, Settings{});
  InspectFlags inspect_options;
  inspect
      ->add_option("--pixel", inspect_options.pixel,
                   "the pixel to inspect, from the top left of the --width x --height image")
      ->type_name("X,Y")
      ->required();
  inspect->add_option("--top", inspect_options.top, "table rows per hit (the JSON has all)")
      ->type_name("N")
      ->default_val(kDefaultInspectTop)
      ->check(decimal_count());
  inspect->add_option("--json", inspect_options.json, "the complete lists (- for standard output)")
      ->type_name("FILE.json")
      ->check(non_empty_value());

  CLI::App* export_command =
      cli.add_subcommand("export", "write a scene model's level (or a scene file) as a scene file");
  ExportFlags export_flags;
  add_export_flags(*export_command, export_flags);

  CLI::App* bench =
      cli.add_subcommand("bench", "the thesis' experiments: results.md, CSVs and plots");
  BenchFlags bench_flags;
  add_bench_flags(*bench, bench_flags);

  CLI::App* snapshot =
      cli.add_subcommand("snapshot", "the default job headless: building snapshot into out/");

  CLI::App* view = cli.add_subcommand(
      "view", "the interactive viewer (the default when a display is available)");
  SceneFlags view_flags;
  const Settings view_defaults = viewer_default_settings();
  add_scene_flags(*view, view_flags, view_defaults);
  viewer::ViewerFlags view_options;
  add_view_flags(*view, view_options);

  check_subcommand_name(cli, argc, argv);
  check_renamed_flags(argc, argv);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ArgumentMismatch& e) {
    throw UsageError(repeated_flag_message(e.what(), argc, argv));
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }

  if (render->parsed()) {
    const Settings settings = apply_scene_flags(render_flags, Settings{});
    refuse_viewer_only_flags(render_flags);
    for (const CLI::Option* option : output_options) {
      if (option->count() > 0 && option->as<std::string>().empty()) {
        throw UsageError(option->get_name() + ": needs a file name, got ''");
      }
    }
    if (reference_option->count() > 0) {
      if (reference != reference_name) {
        throw UsageError("--reference: must be " + reference_name + ", got '" + reference + "'");
      }
      outputs.reference_rt = true;
    }
    if (fail_above_option->count() > 0) outputs.fail_above = parse_accuracy_gate(fail_above);
    if (heatmap_range_option->count() > 0) {
      outputs.heatmap_range = parse_heatmap_range(heatmap_range);
      // It draws the heatmaps and sets the stats' ranges: with neither it would change nothing.
      const bool heatmap = std::any_of(outputs.heatmaps.begin(), outputs.heatmaps.end(),
                                       [](const auto& h) { return !h.second.empty(); });
      if (!heatmap && outputs.stats.empty()) {
        throw UsageError(
            "--heatmap-range: no heatmap (--heatmap-lights, ...) or --stats is "
            "written, so it would change nothing, got '" +
            heatmap_range + "'");
      }
    }
    return run_render(settings, outputs);
  }
  if (inspect->parsed()) {
    const Settings settings = apply_scene_flags(inspect_flags, Settings{});
    refuse_viewer_only_flags(inspect_flags);
    refuse_inspect_ignored_flags(inspect_flags);
    return run_inspect(settings, inspect_options);
  }
  if (export_command->parsed()) return run_export(export_flags);
  if (bench->parsed()) return run_bench(bench_flags);
  if (snapshot->parsed()) return run_snapshot();
  if (view->parsed()) {
    const Settings settings = apply_scene_flags(view_flags, view_defaults);
    refuse_size_beside_a_fitted_resolution(view_flags, settings);
    view_options.exposure_given = view_flags.settings.options.at("exposure")->count() > 0;
    view_options.display_given = view_flags.settings.options.at("display")->count() > 0;
    return run_view(settings, view_options);
  }
  if (viewer_display_available()) {
    try {
      return run_view(viewer_default_settings(), viewer::ViewerFlags{});
    } catch (const viewer::NoDisplayError&) {
      // The display DISPLAY names cannot be opened: the headless job instead.
    }
  }
  std::fprintf(
      stderr,
      "levrt: no display to open a window on; writing the headless snapshot into %s instead\n",
      scenes::escape_control_characters((std::filesystem::current_path() / "out").string())
          .c_str());
  return run_snapshot();
}

}  // namespace app
