// `levrt export`: writes the scene --scene names (a model's level, or a scene file) as a scene
// file (scenes/README.md). Rendering the file gives the same image, bit for bit, and the same
// light hierarchy as rendering the model, because both go through one instantiation.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "app/settings.h"

namespace app {

// The export subcommand's flags: --scene and --level as in the settings table, --lights, --out.
struct ExportFlags {
  std::string scene, level, lights, out;
  CLI::Option* scene_option = nullptr;
  CLI::Option* level_option = nullptr;
  CLI::Option* lights_option = nullptr;
  CLI::Option* out_option = nullptr;
};

void add_export_flags(CLI::App& command, ExportFlags& flags);

// Validates the flags (UsageError, one line) and the output path before any work, then writes
// the file to a temporary name and renames it.
int run_export(const ExportFlags& flags);

}  // namespace app
