// What the viewer's frame loop (viewer_app.cpp) does with the render worker's results each frame:
// the status and tiles taken, the error image kept current against the rt reference, a trade
// point added once a render and its reference compare every pixel, the picture composed for the
// screen, and the tests a scripted await or a snapshot waits on (settled, preview shown).
#pragma once

#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "app/viewer/frame_log.h"
#include "app/viewer/gl_texture.h"
#include "app/viewer/render_worker.h"
#include "app/viewer/viewer_state.h"
#include "renderer/display_transform.h"
#include "renderer/heatmap.h"

namespace app::viewer {

using Clock = std::chrono::steady_clock;

inline double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The texture shown and what it was composed from (recomposed when any of it changes).
struct Picture {
  GlTexture texture;
  std::uint64_t image_version = ~0ull;
  std::uint64_t error_version = ~0ull;
  ViewMode view = ViewMode::image;
  double mask_threshold_pct = -1.0;
  int rt_from_x = -1;  // A/B: the first column showing rt
  std::optional<renderer::HeatmapRange> locked_range;
  std::uint64_t reference_version = ~0ull;
  // The exposure and curve composed with (NaN: none yet).
  renderer::Display display{std::numeric_limits<double>::quiet_NaN(),
                            renderer::DisplayCurve::linear};
  Clock::time_point composed;
  std::vector<std::uint8_t> rgba;
};

// The error image's inputs when it was last computed.
struct ErrorClock {
  std::uint64_t image_version = ~0ull;
  std::uint64_t reference_version = ~0ull;
  float exposure_scale = 0.0f;  // the displayed exposure the error was computed at
  std::uint64_t computed = 0;   // bumps with every new error image
  Clock::time_point at;
};

// At least `levels` preview levels of the render the worker shows have reached the screen (all
// of them when it has fewer).
bool preview_shown(const ViewerState& state, int levels);
bool preview_complete(const ViewerState& state);

// Takes the worker's status and every tile it posted since the last frame into the state.
void take_worker_results(ViewerState& state, RenderWorker& worker, FrameLog& log,
                         Clock::time_point now);

// Recomputes the error image when the image or the reference changed, at most every quarter
// second unless forced.
void update_error(ViewerState& state, ErrorClock& clock, Clock::time_point now, bool force);

// A render whose pass 0 is done makes one trade point once every pixel it rendered is compared
// with the reference of the same view, and the point follows the error as both render more passes.
void add_trade_point_when_ready(ViewerState& state, ErrorClock& clock, Clock::time_point now);

// Composes the view into the picture's texture when an input changed, at most 30 times a
// second unless forced (an exposure or curve change re-maps at once).
void compose_picture(ViewerState& state, Picture& picture, const ErrorClock& clock,
                     Clock::time_point now, bool force);

// All the work is done when the worker has taken the last request, has nothing left to render
// (the reference included, when asked for) and the UI holds every tile.
bool render_settled(const ViewerState& state, std::uint64_t last_posted);

// The latest request's preview levels are all on screen (or its render is past them).
bool preview_settled(const ViewerState& state, std::uint64_t last_posted);

}  // namespace app::viewer
