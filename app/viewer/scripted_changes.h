// Scripted mode for tests and CI: `--set key=value@frame` changes a control at a UI frame, as if
// the user had done it. Keys are the settings table's names, plus `lights` (a light count of the
// scene), `view` (a view name of app/view_table.h), `reference` (on|off), `ab` (rt|method: the
// picture A/B shows), `swipe` (a divider position in [0, 1], or off), `mask_threshold` (the error
// mask's, in percent), `range_lock` (on|off: lock the heatmap range on screen), `hover` (X,Y in
// image pixels, inside a typed-size image: show that pixel's tooltip; scripted mode ignores the
// real mouse), and the actions `window` (resize the window to WIDTHxHEIGHT, as a user dragging its
// border; the frame count holds until the window has that size), `snapshot` (save into a folder),
// `screenshot` (write the window to a PNG), `drop` (a file dropped on the window: a scene file
// opens, app/viewer/scene_opening.h), `copy=camera` (the Copy camera button), `await=idle` (hold
// the frame count until the render, and the reference if requested, are complete), `await=preview`
// (hold it until the coarse preview of the latest change is on screen), `memory=report` (print the
// process's current resident memory, for the soak test that watches it grow over thousands of
// changes) and `trade=report` (print the trade plot's points, with the reference they belong to).
// `--script FILE` reads the same changes, one per line, for scripts too long for a command line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

enum class ScriptAction { none, resize_window, snapshot, screenshot, await_idle, await_preview };

struct ScriptedChange {
  std::string key;
  std::string value;
  int frame = 0;
};

// WIDTHxHEIGHT, from 320x240 to kMaxImageSide a side (--window and the scripted `window` key);
// false when malformed.
bool parse_window_size(const std::string& text, int& width, int& height);

// Throws UsageError ("--set: ...") for a malformed change or a value its key rejects.
ScriptedChange parse_scripted_change(const std::string& text);
std::vector<ScriptedChange> parse_scripted_changes(const std::vector<std::string>& texts);

// A --script file's limit, checked before it is read (a million changes' worth of lines).
inline constexpr std::uintmax_t kMaxScriptFileBytes = std::uintmax_t{16} << 20;

// The lines of a --script file, empty lines skipped (and a CRLF line's '\r'); throws UsageError
// when it cannot be read, is not a regular file (a pipe or device is refused before it is
// opened), is larger than kMaxScriptFileBytes, or has a line parse_scripted_change refuses
// (named by the file and the line number).
std::vector<std::string> read_script_file(const std::string& path);

// Resident memory now (not the peak: /proc/self/statm), 0 where /proc is not mounted.
std::uint64_t current_resident_bytes();

// Before the window opens, refuses (UsageError naming the change) what the script would only
// fail at when it runs, after earlier screenshots were written: a change at a frame past the
// last of `frames` (0: the session runs until the window closes), a light count the scene at its
// frame does not have, settings a render refuses (an image over the memory budget, one
// missed-light draw), and a hover or inspected pixel outside a typed-size image. The settings at a
// change are the initial ones with the script's changes up to that frame applied.
void check_script(const std::vector<ScriptedChange>& changes, const Settings& initial, int frames);

// Applies a control change to the state, or returns the action the frame loop must perform. A
// light count the current scene does not have is logged (check_script refused the counts it
// could know).
ScriptAction apply_scripted_change(ViewerState& state, const ScriptedChange& change);

}  // namespace app::viewer
