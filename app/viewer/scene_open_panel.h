// The panel's part of opening scene files (app/viewer/scene_opening.h): a path field under the
// scene control (type or paste a path, Enter or "Open") with the latest problem under it, the
// recent files, and the log pane that shows each message whole, wrapped (a load error names the
// file and the field at fault).
#pragma once

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_scene_open_row(ViewerState& state);
void draw_messages_section(const ViewerState& state);

}  // namespace app::viewer
