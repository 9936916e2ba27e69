#include "app/viewer/scene_opening.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "app/camera_flags.h"
#include "scenes/scene_file.h"

namespace app::viewer {

void log_message(ViewerState& state, const std::string& raw_text, bool problem) {
  // Paths and load errors are the user's bytes: escaped, each message stays one line in the pane
  // and on stderr, and no escape sequence reaches the terminal.
  const std::string text = scenes::escape_control_characters(raw_text);
  state.messages.push_back({text, problem});
  if (state.messages.size() > kMaxLogMessages)
    state.messages.erase(state.messages.begin(),
                         state.messages.end() - static_cast<std::ptrdiff_t>(kMaxLogMessages));
  if (state.print_messages) std::fprintf(stderr, "levrt view: %s\n", text.c_str());
}

bool open_scene_file(ViewerState& state, const std::string& path) {
  if (path.empty()) return false;
  if (!scenes::is_scene_file_name(path)) {
    log_message(state, path + ": not a scene file (a .json, .gltf or .glb file opens)", true);
    return false;
  }
  if (path == state.settings.scene.name) return true;
  const Settings before = state.settings;
  state.settings.scene.name = path;
  settings_changed(state, before, "scene=" + path);
  log_message(state, "opening " + path, false);
  return true;
}

bool open_dropped_files(ViewerState& state, const std::vector<std::string>& paths) {
  bool opened = false;
  for (const std::string& path : paths) {
    if (opened) {
      log_message(state, path + ": ignored (one scene opens at a time)", true);
    } else {
      opened = open_scene_file(state, path);
    }
  }
  return opened;
}

void follow_scene_loads(ViewerState& state) {
  const WorkerStatus& st = state.status;
  if (st.load_error_serial != state.load_errors_seen) {
    state.load_errors_seen = st.load_error_serial;
    log_message(state,
                "cannot open " + st.load_error_scene + ": " + st.load_error +
                    (st.scene_serial > 0 ? " (kept " + st.scene + ")" : ""),
                true);
    Settings& s = state.settings;
    if (st.scene_serial > 0 && s.scene.name == st.load_error_scene) {
      s.scene.name = st.scene;
      s.scene.level = st.level;
      s.scene.camera = st.camera_index;
      s.scene.camera_flags = st.camera_flags;
      apply_display_defaults(state);
      state.camera = state.camera_before_scene_change;
      mark_changed(state, "");
    }
  }
  if (st.scene_serial != state.scene_loads_seen) {
    state.scene_loads_seen = st.scene_serial;
    if (scenes::is_scene_file_name(st.scene)) {
      auto& recent = state.recent_scenes;
      recent.erase(std::remove(recent.begin(), recent.end(), st.scene), recent.end());
      recent.insert(recent.begin(), st.scene);
      if (recent.size() > kMaxRecentScenes) recent.resize(kMaxRecentScenes);
    }
  }
}

void copy_camera_flags(ViewerState& state) {
  // Before the scene has loaded its preset camera is not known: no made-up view is given out.
  if (!scene_ready(state)) {
    log_message(state, "camera: not known until the scene has loaded; copy it once it is shown",
                true);
    return;
  }
  const std::string flags =
      camera_flags_text(world_camera(current_camera(state), state.status.world_origin));
  if (ImGui::GetCurrentContext()) ImGui::SetClipboardText(flags.c_str());
  log_message(state, "camera: " + flags, false);
}

}  // namespace app::viewer
