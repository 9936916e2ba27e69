#include "app/view_command.h"

#include <cstdlib>
#include <limits>

#ifdef LEVRT_HAS_VIEWER
#include "app/viewer/scripted_changes.h"
#include "app/viewer/viewer_app.h"
#endif

namespace app {

const CLI::Validator& non_empty_value() {
  static const CLI::Validator check(
      [](std::string& value) { return value.empty() ? std::string("needs a value, got ''") : ""; },
      "", "non-empty");
  return check;
}

void add_view_flags(CLI::App& command, viewer::ViewerFlags& flags) {
  // Decimal digits only: CLI11's range check called '1e3' "not in range 0 to 2147483647".
  static const CLI::Validator frame_count(
      [](std::string& value) {
        const std::string range =
            "must be an integer in [0, " + std::to_string(std::numeric_limits<int>::max()) + "]";
        if (value.empty() || value.size() > 10 ||
            value.find_first_not_of("0123456789") != std::string::npos ||
            std::stoll(value) > std::numeric_limits<int>::max()) {
          return range + ", got '" + value + "'";
        }
        return std::string();
      },
      "", "frame count");
  command
      .add_option("--frames", flags.frames,
                  "scripted: run this many UI frames, then exit (0, the default: interactive)")
      ->check(frame_count);
  command
      .add_option("--screenshot", flags.screenshot,
                  "scripted: write the window to this PNG after the last frame")
      ->check(non_empty_value());
  command.add_option(
      "--set", flags.changes,
      "scripted: change a control at a frame, key=value@frame (a setting, lights, view, "
      "reference, ab, swipe, mask_threshold, range_lock, hover, inspect, inspect_row, window, "
      "snapshot, screenshot, drop, copy, await, memory, trade)");
  command
      .add_option("--script", flags.script,
                  "scripted: a file of --set changes, one key=value@frame per line")
      ->check(non_empty_value());
  command.add_flag("--report-fps", flags.report_fps,
                   "print UI frame times and first-tile latencies at exit");
  command.add_option("--window", flags.window, "window size, WIDTHxHEIGHT")
      ->check(non_empty_value());
  command.add_flag("--real-input", flags.real_input,
                   "scripted: let the real mouse drive the picture as well as the panel");
  command
      .add_option("--controls", flags.controls,
                  "write the panel's control rectangles and the settings to this JSON file "
                  "whenever they change (for tests driving the window with real input)")
      ->check(non_empty_value());
}

bool viewer_display_available() {
#ifdef LEVRT_HAS_VIEWER
  const char* display = std::getenv("DISPLAY");
  return display != nullptr && display[0] != '\0';
#else
  return false;
#endif
}

int run_view(const Settings& settings, const viewer::ViewerFlags& flags) {
#ifdef LEVRT_HAS_VIEWER
  if (flags.script.empty()) return viewer::run_viewer(settings, flags);
  viewer::ViewerFlags with_script = flags;
  with_script.changes = viewer::read_script_file(flags.script);
  with_script.changes.insert(with_script.changes.end(), flags.changes.begin(), flags.changes.end());
  return viewer::run_viewer(settings, with_script);
#else
  (void)settings;
  (void)flags;
  throw viewer::NoDisplayError(
      "view: this levrt was built without the viewer; use `levrt render` to render headless");
#endif
}

}  // namespace app
