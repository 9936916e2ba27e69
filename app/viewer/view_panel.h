// The view switch (image, lights tested, nodes visited, error against rt) and the legend of the
// heatmap on screen: the viridis bar over the rendered pixels' min .. max (heatmap_scale.h) with
// ticks in the value's own units. A legend never shows a scale that is not there: nothing
// rendered, a field of zeros (said in words) and a constant field (its value) have no bar.
#pragma once

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_view_section(ViewerState& state);

// The legend of one heatmap: `range` is its value range over the rendered pixels, `rendered`
// whether there are any, `method` the method that rendered them.
void draw_heatmap_legend(const ViewModeInfo& info, const renderer::HeatmapRange& range,
                         bool rendered, const std::string& method);

}  // namespace app::viewer
