#include "app/export_command.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "app/output_files.h"
#include "app/scene_loading.h"
#include "scenes/scene_file.h"
#include "scenes/scene_inputs.h"

namespace app {
namespace {

// A scene named by its file's stem keeps that name's bytes, which need not be UTF-8 (a Latin-1
// file name); a scene file is JSON, so its invalid bytes are written as U+FFFD.
std::string utf8_name(const std::string& name) {
  const std::string quoted =
      nlohmann::json(name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted).get<std::string>();
}

}  // namespace

void add_export_flags(CLI::App& command, ExportFlags& flags) {
  flags.scene_option = command.add_option("--scene", flags.scene, find_setting("scene")->help);
  flags.level_option = command.add_option("--level", flags.level, find_setting("level")->help);
  flags.lights_option = command.add_option("--lights", flags.lights,
                                           "light count (selects the level with that many lights)");
  flags.out_option = command.add_option("--out", flags.out, "scene file to write (JSON)");
}

int run_export(const ExportFlags& flags) {
  Settings settings;
  if (flags.scene_option->count() > 0) set_setting(settings, *find_setting("scene"), flags.scene);
  if (flags.level_option->count() > 0) {
    set_setting(settings, *find_setting("level"), flags.level);
    // As `render` says: a file's level is the one it was exported at, not chosen here.
    if (is_scene_file(settings.scene))
      throw UsageError("--level: a scene file has no levels, got '" + flags.level + "'");
  }
  if (flags.lights_option->count() > 0) {
    if (flags.level_option->count() > 0)
      throw UsageError("--lights: give --level or --lights, not both");
    apply_light_count_flag(settings.scene, flags.lights);
  }
  if (flags.out_option->count() == 0) throw UsageError("--out: export needs a file name");
  if (flags.out.empty()) throw UsageError("--out: needs a file name, got ''");
  check_output_paths({{"--out", flags.out, ".json", "a scene file"}},
                     scenes::scene_input_files(settings.scene.name));
  scenes::SceneDescription description = describe_scene(settings.scene);
  description.name = utf8_name(description.name);
  std::string text;
  try {
    text = scenes::scene_file_json(description);
  } catch (const std::invalid_argument& e) {
    // What a scene file cannot hold (a glTF's meshes or suns), named with the scene it came from.
    throw std::invalid_argument(settings.scene.name + ": " + e.what());
  }
  app::write_text_file(flags.out, text);
  // With --out - the scene file is standard output, so the note goes to stderr.
  std::fprintf(flags.out == app::kStandardOutputName ? stderr : stdout,
               "wrote %s: %s level %d, %zu masters\n",
               scenes::escape_control_characters(flags.out).c_str(),
               scenes::escape_control_characters(description.name).c_str(), description.level,
               description.masters.size());
  return 0;
}

}  // namespace app
