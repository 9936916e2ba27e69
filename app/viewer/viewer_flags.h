// The flags only the viewer has (scripted frames, screenshot, scripted changes, window size), and
// the error it raises when no window can open. Header-only, so `levrt view` can parse them (and
// say there is no viewer) in a build without the viewer; app/view_command registers them.
#pragma once

#include <string>
#include <vector>

#include "app/settings.h"

namespace app::viewer {

struct ViewerFlags {
  int frames = 0;                    // scripted: UI frames to run, 0 = until the window closes
  std::string screenshot;            // scripted: PNG of the whole window after the last frame
  std::vector<std::string> changes;  // scripted: "key=value@frame"
  std::string script;                // scripted: a file of changes, one "key=value@frame" per line
  bool report_fps = false;           // print frame times and first-tile latencies at exit
  std::string window = "1280x800";   // window size, WIDTHxHEIGHT
  bool real_input = false;           // scripted: the real mouse drives the picture too
  std::string controls;              // write the named controls' rectangles and the settings here
  // Whether the command line gave --exposure or --display: a scene opened later gets its own
  // defaults (app/settings.h, apply_scene_display_defaults) for those it did not give.
  bool exposure_given = false;
  bool display_given = false;
};

// There is no display to open a window on (exit code 2, like any usage error).
struct NoDisplayError : UsageError {
  using UsageError::UsageError;
};

}  // namespace app::viewer
