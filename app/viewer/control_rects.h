// Where the panel's named controls are on screen, for tests that drive the viewer with real X
// input (`levrt view --controls FILE`): after each named control the panel records its screen
// rectangle, and the frame loop writes them, with the settings and view they produced, to a
// small JSON file whenever they change. A test reads the rectangles instead of guessing pixels
// and reads the settings back to see what its clicks did.
#pragma once

#include <string>
#include <vector>

#include "app/settings.h"
#include "app/view_table.h"

namespace app::viewer {

struct ControlRect {
  std::string name;
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;  // window pixels, x1/y1 exclusive
  bool hovered = false;                              // under the mouse pointer in this frame
};

// Null when the viewer records nothing (the panel's calls are then no-ops).
using ControlRects = std::vector<ControlRect>;

// The last ImGui item's rectangle.
void record_item(ControlRects* rects, const std::string& name);
// A part of the last item (a +/- button of a number field): hovered when the item is and the
// pointer is inside the part.
void record_rect(ControlRects* rects, const std::string& name, float x0, float y0, float x1,
                 float y1);

// {"controls": {name: [x0, y0, x1, y1], ...}, "settings": {name: text, ...}, "unused": {name:
// why, ...} (the settings greyed out for these settings), "view": name,
// "mouse_busy": a control is held or the mouse is down, "hovered": the control under the pointer
// or ""}. A test waits for its target to be hovered before clicking: the window then surely
// receives the pointer. A test waits for mouse_busy false
// before its next click, so a release and the next press never reach ImGui in one frame.
std::string controls_json(const ControlRects& rects, const Settings& settings, ViewMode view,
                          bool mouse_busy);

}  // namespace app::viewer
