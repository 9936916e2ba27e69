// Opening scene files while the viewer runs: a path typed into the panel's field, a file dropped
// on the window (GLFW's drop callback), a recent file, or the scripted `scene=`/`drop=` changes
// all end in open_scene_file, which asks the worker for the file like any other setting. The
// worker builds the new scene before letting the old one go (app/viewer/render_worker.h), so a
// file that cannot be read leaves the old scene on screen: follow_scene_loads logs the whole
// message and returns the settings and camera to the scene still loaded. "Copy camera" gives the
// view back as flags, so a scene opened by hand can be rendered headless from the same place.
#pragma once

#include <string>
#include <vector>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

inline constexpr std::size_t kMaxRecentScenes = 8;
inline constexpr std::size_t kMaxLogMessages = 64;

// Appends a message to the log pane (the oldest go past kMaxLogMessages); printed to stderr as
// well when state.print_messages is set. Control characters are escaped (`\n`, `\x1b`).
void log_message(ViewerState& state, const std::string& text, bool problem);

// Asks for the scene file at `path` (a .json, .gltf or .glb, as --scene takes it). A path that
// names no scene file is logged and refused (false): nothing is requested.
bool open_scene_file(ViewerState& state, const std::string& path);

// Files dropped on the window: the first one that names a scene file is opened, the others are
// logged as ignored. Returns whether one was opened.
bool open_dropped_files(ViewerState& state, const std::vector<std::string>& paths);

// After the worker's status is taken: a failed load is logged whole and undone in the settings
// (scene, level, light scale, camera index and the user's camera go back to what is loaded);
// a scene file that loaded goes to the front of the recent list.
void follow_scene_loads(ViewerState& state);

// The current view as --camera-* flags (app/camera_flags.h): to the clipboard and the log; while
// the scene the settings name is loading, a message saying so instead.
void copy_camera_flags(ViewerState& state);

}  // namespace app::viewer
