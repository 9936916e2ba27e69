// The one service above the render step that every front end calls: `levrt render`, the viewer's
// render worker and its rt reference, and every bench experiment. A RenderJob makes the render
// state (timing the setup: the method's selector, a `lev` state's extent volumes) and runs passes
// on it; its result is one RenderResult (framebuffer, totals, the rendered pixels, timings), so
// no front end collects these in a copy of its own. render_passes is the headless loop over it.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "renderer/framebuffer.h"
#include "renderer/render.h"

namespace renderer {

struct RenderResult {
  Framebuffer framebuffer;
  FramebufferTotals totals;
  // The pixels the (possibly subsampled) render produced, 8-bit RGB in pixel order: what pixel
  // errors compare.
  std::vector<std::uint8_t> rendered_rgb;
  std::uint64_t rendered_pixels = 0;
  int passes = 0;
  double setup_seconds = 0.0;  // make_render_state: selector and extent volumes
  // The process' CPU time over that set-up (every thread; process_cpu_time.h). It does not grow
  // with the pixels rendered, so a subsampled render's time is scaled to the frame without it.
  double setup_cpu_seconds = 0.0;
  double render_seconds = 0.0;   // wall time inside the passes
  std::size_t method_bytes = 0;  // the method's own bookkeeping (AST)
  // The probe that chose between the method and rt's loop (rt_fallback.h), when one was made.
  std::optional<RtFallbackProbe> rt_fallback;
};

class RenderJob {
 public:
  // The state refers to scene and rays; they must outlive the job.
  RenderJob(const Scene& scene, const RayScene& rays, const RenderSettings& settings);

  // One more pass (render_pass); false when *cancel stopped it.
  bool pass(const std::atomic<bool>* cancel = nullptr,
            const TileDoneCallback& on_tile_done = nullptr, int preview_step = 1);

  RenderState& state() { return *state_; }
  const RenderState& state() const { return *state_; }
  double setup_seconds() const { return setup_seconds_; }
  double setup_cpu_seconds() const { return setup_cpu_seconds_; }
  RenderResult result() const;

 private:
  RenderStatePtr state_;
  double setup_seconds_ = 0.0;
  double setup_cpu_seconds_ = 0.0;
};

// The pixels of `framebuffer` with at least one sample, as 8-bit RGB.
std::vector<std::uint8_t> rendered_rgb8(const Framebuffer& framebuffer);

// Called after each complete pass with the passes done and the render's wall time so far.
using PassDoneCallback = std::function<void(int passes_done, double render_seconds)>;

// What a caller of render_passes follows of the loop (each may be empty): the job once made
// (before its first pass), each pass as it starts (from 1), each tile done (any thread), each
// pass done.
struct PassHooks {
  std::function<void(const RenderState& state)> on_ready;
  std::function<void(int pass)> on_pass_start;
  TileDoneCallback on_tile_done;
  PassDoneCallback on_pass_done;
};

// `passes` passes of a new job. Returns false (and leaves *result untouched) when *cancel stopped
// a pass.
bool render_passes(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                   int passes, RenderResult& result, const std::atomic<bool>* cancel,
                   const PassHooks& hooks);
bool render_passes(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                   int passes, RenderResult& result, const std::atomic<bool>* cancel = nullptr,
                   const PassDoneCallback& on_pass_done = nullptr);

}  // namespace renderer
