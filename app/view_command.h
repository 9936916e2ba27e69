// `levrt view`: the interactive viewer's command-line side. It registers the flags that only the
// viewer has (app/viewer/viewer_flags.h) and decides whether a viewer can open at all; the viewer
// itself lives in app/viewer/ and is only built when LEVRT_HAS_VIEWER.
#pragma once

#include <CLI/CLI.hpp>

#include "app/settings.h"
#include "app/viewer/viewer_flags.h"

namespace app {

// Passes the viewer accumulates when --spp is not given (the CLI's default is one pass).
inline constexpr int kViewerDefaultPasses = 64;

// The settings the viewer starts from where a flag is not given (`view --help` shows them).
inline Settings viewer_default_settings() {
  Settings settings;
  settings.image.spp = kViewerDefaultPasses;
  return settings;
}

// Refuses an empty value for a flag whose empty text would otherwise mean "not given" (the
// camera flags, inspect's --json, the viewer's files). CLI11 prefixes the flag: "--fov: needs a
// value, got ''".
const CLI::Validator& non_empty_value();

void add_view_flags(CLI::App& command, viewer::ViewerFlags& flags);

// True when levrt was built with the viewer and DISPLAY names a display.
bool viewer_display_available();

// Opens the viewer; throws viewer::NoDisplayError without a display, UsageError for bad flags.
int run_view(const Settings& settings, const viewer::ViewerFlags& flags);

}  // namespace app
