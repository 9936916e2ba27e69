// The view switch (image, lights tested, nodes visited, error against rt) and the legend of the
// heatmap on screen: the viridis bar on log(1 + value) with ticks in the value's own units.
#pragma once

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_view_section(ViewerState& state);

// The legend of one heatmap: `range` is its value range over the rendered pixels.
void draw_heatmap_legend(const ViewModeInfo& info, const renderer::HeatmapRange& range);

}  // namespace app::viewer
