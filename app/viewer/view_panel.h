// The view switch (a radio button per row of app/view_table.h) and the legend of the view on
// screen, by its colour map: the viridis bar over the rendered pixels' min .. max
// (heatmap_scale.h) with ticks in the value's own units, the diverging bar over its fixed range,
// or the mask's threshold control with the share of pixels above it. A legend never shows a scale
// that is not there: nothing rendered, a field of zeros (said in words) and a constant field (its
// value) have no bar.
#pragma once

#include "app/viewer/viewer_state.h"

namespace app::viewer {

void draw_view_section(ViewerState& state);

// The legend of one heatmap: `range` is its value range over the rendered pixels, `rendered`
// whether there are any, `method` the method that rendered them.
void draw_heatmap_legend(const ViewInfo& info, const renderer::HeatmapRange& range, bool rendered,
                         const std::string& method);

}  // namespace app::viewer
