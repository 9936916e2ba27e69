// Live statistics of the render on screen (time per pass, Mrays/s, shading points, lights tested
// and nodes visited per point, hierarchy memory, build and render set-up time, pixel error) and the
// rt reference's controls: compute, progress, cancel.
#pragma once

#include <chrono>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

// The statistics table has these rows whatever the method, view or render state (a value not
// known says so in its row), so the results pane's height, and with it the picture's, follows
// the window alone: a method change never moves the picture's border.
inline constexpr int kStatsRows = 17;

// The height of draw_stats_section's table (kStatsRows rows of one line), from the style alone.
float stats_section_height();

void draw_status_line(const ViewerState& state, std::chrono::steady_clock::time_point now);
void draw_stats_section(const ViewerState& state, std::chrono::steady_clock::time_point now);
void draw_reference_section(ViewerState& state, std::chrono::steady_clock::time_point now);

}  // namespace app::viewer
