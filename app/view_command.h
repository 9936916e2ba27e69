// `levrt view`: the interactive viewer's command-line side. It holds the flags that only the
// viewer has (scripted frames, screenshot, scripted changes) and decides whether a viewer can
// open at all; the viewer itself lives in app/viewer/ and is only built when LEVRT_HAS_VIEWER.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/settings.h"

namespace app {

// Passes the viewer accumulates when --spp is not given (the CLI's default is one pass).
inline constexpr int kViewerDefaultPasses = 64;

struct ViewFlags {
  int frames = 0;                    // scripted: UI frames to run, 0 = until the window closes
  std::string screenshot;            // scripted: PNG of the whole window after the last frame
  std::vector<std::string> changes;  // scripted: "key=value@frame"
  std::string script;                // scripted: a file of changes, one "key=value@frame" per line
  bool report_fps = false;           // print frame times and first-tile latencies at exit
  std::string window = "1280x800";   // window size, WIDTHxHEIGHT
  bool real_input = false;           // scripted: the real mouse drives the picture too
  std::string controls;              // write the named controls' rectangles and the settings here
};

// There is no display to open a window on (exit code 2, like any usage error).
struct NoDisplayError : UsageError {
  using UsageError::UsageError;
};

void add_view_flags(CLI::App& command, ViewFlags& flags);

// True when levrt was built with the viewer and DISPLAY names a display.
bool viewer_display_available();

// Opens the viewer; throws NoDisplayError without a display, UsageError for bad flags.
int run_view(const Settings& settings, const ViewFlags& flags);

}  // namespace app
