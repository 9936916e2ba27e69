// Live statistics of the render on screen (time per pass, Mrays/s, shading points, lights tested
// and nodes visited per point, hierarchy memory, build and render set-up time, pixel error) and the
// rt reference's controls: compute, progress, cancel.
#pragma once

#include <chrono>

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_status_line(const ViewerState& state, std::chrono::steady_clock::time_point now);
void draw_stats_section(const ViewerState& state, std::chrono::steady_clock::time_point now);
void draw_reference_section(ViewerState& state, std::chrono::steady_clock::time_point now);

}  // namespace app::viewer
