// Everything the viewer's UI thread knows, in one plain struct: the settings and camera the user
// chose, what to show, and the copies of the worker's results (status, images, errors, trade
// points). Panels and scripted changes edit it through the verbs below, which mark the request
// dirty; the frame loop posts one request per frame at most.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/output_files.h"
#include "app/settings.h"
#include "app/view_table.h"
#include "app/viewer/control_rects.h"
#include "app/viewer/display_image.h"
#include "app/viewer/render_worker.h"
#include "app/viewer/trade_plot.h"
#include "renderer/camera.h"
#include "renderer/heatmap.h"

namespace app::viewer {

// A line of the log pane; a problem (a file that did not open) is drawn in a warning colour.
struct LogMessage {
  std::string text;
  bool problem = false;
};

struct ViewerState {
  Settings settings;
  std::optional<renderer::Camera> camera;  // empty: the scene's preset
  ViewMode view = ViewMode::image;
  bool want_reference = false;
  double mask_threshold_pct = kDefaultMaskThresholdPct;  // the mask view's
  // A/B against rt (the image view): show rt's picture instead of the method's, or split the
  // picture at a divider (fraction of its width from the left: the method left, rt right).
  bool ab_rt = false;
  std::optional<double> swipe;
  bool swipe_dragging = false;  // the mouse holds the divider
  // Heatmap ranges locked by the legend's lock, by view, so renders compare on one scale.
  std::map<ViewMode, renderer::HeatmapRange> locked_ranges;

  bool request_dirty = true;  // post a request at the end of this frame
  std::string change_label;   // what changed, for the latency report (empty: not reported)

  WorkerStatus status;
  DisplayImage image;
  PreviewImage preview;  // shown where the render has not arrived yet; never saved
  DisplayImage reference;
  ErrorImage error;
  std::vector<TileRect> in_flight;
  TradePlot trade;
  renderer::HeatmapRange heatmap_range;  // of the view on screen
  double ui_fps = 0.0;
  // The picture's area in framebuffer pixels, as the last frame laid it out (the fit resolution
  // renders at this size), and whether a fit resize waits for the window to settle.
  int image_area_width = 0;
  int image_area_height = 0;
  bool fit_pending = false;
  std::string snapshot_folder = "out";
  // Save snapshot was pressed: the snapshot is taken once the image holds whole passes
  // (take_requested_snapshot), so that it is the image `levrt render --spp N` writes.
  bool snapshot_requested = false;
  // The outputs' rule (app/output_files.h) for snapshots: the files the viewer reads besides the
  // scene the settings name (the script), and its other outputs (screenshots, controls).
  std::vector<std::string> other_inputs;
  std::vector<OutputPath> other_outputs;

  // Scripted mode ignores the real mouse over the picture (tests must not depend on where the
  // pointer happens to be) and can hover a pixel instead.
  bool mouse_input = true;
  std::optional<TileRect> scripted_hover;  // the pixel x0, y0
  // The inspector: the pixel pinned by a click (or `--set inspect=X,Y`) until cleared, and the
  // row of its list selected (-1: none), whose extent volume the image outlines.
  std::optional<std::array<int, 2>> inspect_pixel;
  int inspect_row = -1;
  // `--controls FILE`: the panel records its named controls' rectangles each frame.
  bool record_controls = false;
  ControlRects control_rects;

  // Opening scene files (app/viewer/scene_opening.h): the panel's path field, the files loaded
  // this session (newest first), the log pane's messages (oldest first) and whether they are
  // also printed (scripted sessions print them, so a test or CI log sees them).
  std::string scene_path_field;
  std::vector<std::string> recent_scenes;
  std::vector<LogMessage> messages;
  bool print_messages = false;
  // Where the scripted reports (memory, trade plot) and the closing notes go: standard output,
  // or stderr when an output (a screenshot, the controls) is standard output, so that stream
  // holds that output alone.
  std::FILE* notes = stdout;
  std::uint64_t load_errors_seen = 0;
  std::uint64_t scene_loads_seen = 0;
  // The camera the user had before asking for another scene: a scene that cannot be loaded
  // gives it back, with the old scene.
  std::optional<renderer::Camera> camera_before_scene_change;
  // Whether the user chose the exposure or the display curve (a flag, the panel, a script): a
  // scene opened later keeps a choice, and gets its own default for the other (glTF files auto
  // and neutral, the rest EV 0 and linear: apply_scene_display_defaults, as `levrt render`
  // gives them): apply_display_defaults. A scene that cannot be loaded gives them back.
  bool exposure_chosen = false;
  bool display_chosen = false;
};

// Marks the request dirty; `label` names the change in the latency report.
void mark_changed(ViewerState& state, const std::string& label);

// The display of the scene the settings name for what the user did not choose (exposure_chosen,
// display_chosen): glTF files auto and neutral, the rest EV 0 and linear, as `levrt render` gives
// them when --exposure and --display are not given.
void apply_display_defaults(ViewerState& state);

// Call after editing state.settings: a new scene gets its default level, a new scene or level
// its preset camera, a typed width or height selects the typed resolution, and a new view drops
// the reference unless the view on screen compares with it.
void settings_changed(ViewerState& state, const Settings& before, const std::string& label);

// The render size of a fit resolution for an image area of area_width x area_height pixels:
// 1/divisor of it, at least 1x1, and scaled down (the aspect kept) to what the memory budget
// allows a render with the rt reference (app/render_command.h), so no window size makes the
// render fail; such a picture is shown enlarged, as fit/2's is.
std::array<int, 2> fit_render_size(int area_width, int area_height, int divisor);

// The image area asks for a new render size (fit resolution): like a typed size, but the
// resolution stays fit and a reference asked for is kept asking for (at the new size).
void set_fit_size(ViewerState& state, int width, int height);

// Shows a view; one that compares with rt asks for the reference.
void select_view(ViewerState& state, ViewMode mode);
void set_camera(ViewerState& state, const renderer::Camera& camera);
void reset_camera(ViewerState& state);
void set_want_reference(ViewerState& state, bool want);
// Locks the view on screen's heatmap range as shown now (a min..max range), or unlocks it.
void set_range_lock(ViewerState& state, bool locked);
// The locked range of the view on screen, or of `mode`, if any.
std::optional<renderer::HeatmapRange> locked_range(const ViewerState& state);
std::optional<renderer::HeatmapRange> locked_range(const ViewerState& state, ViewMode mode);
// A/B: show rt's image (asking for the reference) or the method's; split at a divider or not.
void set_ab_rt(ViewerState& state, bool rt);
void set_swipe(ViewerState& state, std::optional<double> divider);
// The first column of the image view that shows rt's picture: 0 for rt, the width for the method
// (or while there is no reference), the divider's column while swiping.
int rt_from_column(const ViewerState& state);
// Pins the inspector on a pixel (image pixels from the top left), or clears it.
void set_inspect_pixel(ViewerState& state, const std::optional<std::array<int, 2>>& pixel);

// True when the worker has loaded the scene the settings name (the preset camera is known).
bool scene_ready(const ViewerState& state);
renderer::Camera current_camera(const ViewerState& state);

// The worker's request: the settings, with the missed-light estimate on (at least
// kDefaultMissedDraws draws) while a view reading it is on screen.
RenderRequest make_request(const ViewerState& state);

}  // namespace app::viewer
