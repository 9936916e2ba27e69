#include "app/viewer/frame_progress.h"

#include <algorithm>

#include "app/view_table.h"
#include "renderer/display_transform.h"

namespace app::viewer {
namespace {

constexpr double kComposeSeconds = 1.0 / 30.0;  // the texture is rebuilt at most this often
constexpr double kErrorSeconds = 0.25;          // and the error image at most this often

bool same_range(const std::optional<renderer::HeatmapRange>& a,
                const std::optional<renderer::HeatmapRange>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->min == b->min && a->max == b->max);
}

}  // namespace

// At least `levels` preview levels of the render the worker shows have reached the screen (all
// of them when it has fewer).
bool preview_shown(const ViewerState& state, int levels) {
  const WorkerStatus& st = state.status;
  const int wanted = std::min(levels, st.preview_levels);
  return st.generation != 0 && st.preview_levels_done >= wanted &&
         (wanted == 0 || state.preview.generation == st.generation);
}

bool preview_complete(const ViewerState& state) {
  return preview_shown(state, state.status.preview_levels);
}

void take_worker_results(ViewerState& state, RenderWorker& worker, FrameLog& log,
                         Clock::time_point now) {
  // Status first: every tile a status refers to was posted before it, so it is in the buffer.
  state.status = worker.status();
  // Auto exposure: the EV the worker chose for the scene is the one shown (until the slider
  // takes over).
  if (state.settings.display.exposure_auto && state.status.scene_serial > 0)
    state.settings.display.exposure_ev = state.status.auto_exposure_ev;
  // Tiles of renders that are gone never arrive (the buffers' floors); the previous render's
  // colours stay as the new one's backdrop.
  if (apply_tile_updates(state.image, worker.take_tiles().updates)) {
    record_first_tile(log, state.image.generation, now);
  }
  if (apply_preview_updates(state.preview, state.image, worker.take_preview_tiles().updates)) {
    record_first_tile(log, state.preview.generation, now);
  }
  if (preview_shown(state, 1)) record_preview(log, state.status.generation, false, now);
  if (preview_complete(state)) record_preview(log, state.status.generation, true, now);

  const TakenTiles reference = worker.take_reference_tiles();
  if (state.reference.generation != 0 && state.reference.generation < reference.floor) {
    clear_display_image(state.reference);
  }
  apply_tile_updates(state.reference, reference.updates);
  // A render that goes on at a new exposure (rt, the samplers, lightcuts) is shown at it: its
  // colours, bound, noise and missed light as a render at that exposure reports them.
  const float exposure_scale = renderer::exposure_scale(state.settings.display.exposure_ev);
  expose_display_image(state.image, exposure_scale);
  expose_display_image(state.reference, exposure_scale);
  state.in_flight = worker.tiles_in_flight();
  follow_reference(state.trade, state.status.reference_generation);
  state.trade.reference_pass0_seconds = state.status.reference_first_pass_seconds;
}

void update_error(ViewerState& state, ErrorClock& clock, Clock::time_point now, bool force) {
  // The errors are in the displayed units: the exposure shown, which the method rendered at
  // when its images depend on it (app::restart_needed).
  const float exposure_scale = renderer::exposure_scale(state.settings.display.exposure_ev);
  if (clock.image_version == state.image.version &&
      clock.reference_version == state.reference.version && clock.exposure_scale == exposure_scale)
    return;
  if (!force && seconds_between(clock.at, now) < kErrorSeconds) return;
  clock.image_version = state.image.version;
  clock.reference_version = state.reference.version;
  clock.exposure_scale = exposure_scale;
  clock.at = now;
  clock.computed += 1;
  if (state.reference.generation == 0) {
    state.error = ErrorImage{};
  } else {
    state.error = compute_error_image(state.image, state.reference, exposure_scale);
  }
}

// A render whose pass 0 is done makes one trade point once every pixel it rendered is compared
// with the reference of the same view, and the point follows the error as both render more passes.
void add_trade_point_when_ready(ViewerState& state, ErrorClock& clock, Clock::time_point now) {
  const WorkerStatus& st = state.status;
  const bool reference_shown =
      st.reference_generation != 0 && state.reference.generation == st.reference_generation;
  const bool pass0_done =
      st.generation != 0 && state.image.generation == st.generation && st.first_pass_seconds >= 0.0;
  if (!reference_shown || !pass0_done) return;
  // The first point at once, and the last once both renders are done; the updates between at
  // the error's own pace.
  const bool settled = st.phase == WorkerPhase::idle && st.reference == ReferencePhase::done;
  update_error(state, clock, now, settled || trade_point_passes(state.trade, st.generation) == 0);
  const ErrorImage& e = state.error;
  const bool all_compared = e.pixels_compared > 0 && e.pixels_compared == e.pixels_rendered;
  if (!all_compared || e.passes <= trade_point_passes(state.trade, st.generation)) return;
  TradePoint p;
  p.method = st.method;
  p.tolerance = st.tolerance;
  p.relative_error = st.method_choice.relative_error;
  p.lights_per_point = st.method_choice.lights_per_point;
  p.rt_fallback = st.method_choice.rt_fallback;
  p.seconds = st.first_pass_seconds;
  p.error_avg_pct = e.average_pct;
  p.error_max_pct = e.max_pct;
  p.shared_cpu = st.first_pass_shared;
  p.passes = e.passes;
  p.generation = st.generation;
  add_trade_point(state.trade, p);
}

void compose_picture(ViewerState& state, Picture& picture, const ErrorClock& clock,
                     Clock::time_point now, bool force) {
  const bool uses_error = view_info(state.view).needs_reference;
  const int rt_from_x = rt_from_column(state);
  const std::optional<renderer::HeatmapRange> locked = locked_range(state);
  // rt's picture counts while any of it is shown.
  const std::uint64_t reference_version =
      rt_from_x < state.image.width ? state.reference.version : 0;
  const std::uint64_t error_version = uses_error ? clock.computed : 0;
  const renderer::Display display = display_from(state.settings);
  const bool same_display =
      picture.display.exposure_ev == display.exposure_ev && picture.display.curve == display.curve;
  if (picture.image_version == state.image.version && picture.error_version == error_version &&
      picture.view == state.view && picture.mask_threshold_pct == state.mask_threshold_pct &&
      picture.rt_from_x == rt_from_x && picture.reference_version == reference_version &&
      same_range(picture.locked_range, locked) && same_display) {
    return;
  }
  // A new exposure or curve re-maps at once: it is the user's hand on the control.
  if (!force && same_display && seconds_between(picture.composed, now) < kComposeSeconds) return;
  compose_view_rgba(state.image, state.preview, state.error, state.view, picture.rgba,
                    state.heatmap_range, display, state.mask_threshold_pct,
                    AbSplit{&state.reference, rt_from_x}, locked);
  picture.display = display;
  upload_texture(picture.texture, state.image.width, state.image.height, picture.rgba);
  picture.image_version = state.image.version;
  picture.error_version = error_version;
  picture.view = state.view;
  picture.mask_threshold_pct = state.mask_threshold_pct;
  picture.rt_from_x = rt_from_x;
  picture.locked_range = locked;
  picture.reference_version = reference_version;
  picture.composed = now;
}

// All the work is done when the worker has taken the last request, has nothing left to render
// (the reference included, when asked for) and the UI holds every tile.
bool render_settled(const ViewerState& state, std::uint64_t last_posted) {
  const WorkerStatus& st = state.status;
  if (state.fit_pending || state.request_dirty || st.request_serial < last_posted) return false;
  if (st.phase == WorkerPhase::failed) return true;
  if (st.phase != WorkerPhase::idle) return false;
  if (state.want_reference && st.reference == ReferencePhase::rendering) return false;
  if (st.inspection_pending) return false;  // the pinned pixel's list is on its way
  return st.generation == 0 || state.image.generation == st.generation;
}

// The latest request's preview levels are all on screen (or its render is past them).
bool preview_settled(const ViewerState& state, std::uint64_t last_posted) {
  const WorkerStatus& st = state.status;
  if (state.fit_pending || state.request_dirty || st.request_serial < last_posted) return false;
  if (st.phase == WorkerPhase::failed || st.generation == 0) return true;
  return preview_complete(state);
}

}  // namespace app::viewer
