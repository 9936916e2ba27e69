// The panel's snapshot section: a folder field and a Save button that hands copies of the image,
// the current heatmap and the stats JSON to a SnapshotWriter, with its progress while it writes.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "app/viewer/snapshot_writer.h"
#include "app/viewer/viewer_state.h"
#include "lev/methods.h"

namespace app::viewer {

// The snapshot's file names before their suffixes: view_SCENE_LIGHTS_METHOD, then the setting the
// method reads (its tolerance or its relative error; a sampler's lights per point as kN when not
// 1), with '/', '\\' and spaces made '_'. A setting the method ignores is not named: two
// snapshots that differ only there are the same render.
std::string snapshot_base_name(const std::string& scene, std::uint64_t light_count,
                               const lev::MethodChoice& choice);

// The files of the render on screen: the image, the view's heatmap (the lights-tested heatmap
// when the image itself is shown) and the stats.
SnapshotJob make_snapshot_job(const ViewerState& state, std::chrono::steady_clock::time_point now);

// Whether the image holds whole passes of the render shown (every tile of its latest pass, and
// the status counting that pass): a snapshot then is `levrt render --spp N`'s image and stats.
// Mid-pass, some tiles hold one sample more than the rest (and before pass 1 is whole, the
// previous render's colours show where no tile has arrived).
bool image_holds_whole_passes(const ViewerState& state);

// Save snapshot asks for one (state.snapshot_requested); once the image holds whole passes and
// no snapshot is being written, its job starts. Call every frame.
void request_snapshot(ViewerState& state);
void take_requested_snapshot(ViewerState& state, SnapshotWriter& writer,
                             std::chrono::steady_clock::time_point now);

void draw_snapshot_section(ViewerState& state, const SnapshotWriter& writer);

}  // namespace app::viewer
