// The panel's snapshot section: a folder field and a Save button that hands copies of the image,
// the current heatmap and the stats JSON to a SnapshotWriter, with its progress while it writes.
#pragma once

#include <chrono>

#include "app/viewer/snapshot_writer.h"
#include "app/viewer/viewer_state.h"

namespace app::viewer {

// The files of the render on screen: the image, the view's heatmap (the lights-tested heatmap
// when the image itself is shown) and the stats.
SnapshotJob make_snapshot_job(const ViewerState& state, std::chrono::steady_clock::time_point now);

void draw_snapshot_section(ViewerState& state, SnapshotWriter& writer,
                           std::chrono::steady_clock::time_point now);

}  // namespace app::viewer
