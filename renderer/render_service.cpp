#include "renderer/render_service.h"

#include <chrono>

#include "renderer/process_cpu_time.h"

namespace renderer {

RenderJob::RenderJob(const Scene& scene, const RayScene& rays, const RenderSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  state_ = make_render_state(scene, rays, settings);
  setup_cpu_seconds_ = process_cpu_seconds() - cpu_start;
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool RenderJob::pass(const std::atomic<bool>* cancel, const TileDoneCallback& on_tile_done,
                     int preview_step) {
  return render_pass(*state_, cancel, on_tile_done, preview_step);
}

std::vector<std::uint8_t> rendered_rgb8(const Framebuffer& framebuffer) {
  const std::vector<std::uint8_t> all = framebuffer_rgb8(framebuffer);
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < framebuffer.samples.size(); ++i) {
    if (framebuffer.samples[i] == 0) continue;
    out.insert(out.end(), all.begin() + static_cast<std::ptrdiff_t>(3 * i),
               all.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
  }
  return out;
}

RenderResult RenderJob::result() const {
  RenderResult r;
  r.framebuffer = render_framebuffer(*state_);
  r.totals = sum_framebuffer(r.framebuffer);
  r.rendered_rgb = rendered_rgb8(r.framebuffer);
  r.rendered_pixels = r.rendered_rgb.size() / 3;
  r.passes = render_passes_done(*state_);
  r.setup_seconds = setup_seconds_;
  r.setup_cpu_seconds = setup_cpu_seconds_;
  r.render_seconds = render_seconds(*state_);
  r.method_bytes = render_selector(*state_).bookkeeping_bytes();
  if (const RtFallbackProbe* probe = render_rt_fallback(*state_)) r.rt_fallback = *probe;
  return r;
}

bool render_passes(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                   int passes, RenderResult& result, const std::atomic<bool>* cancel,
                   const PassHooks& hooks) {
  RenderJob job(scene, rays, settings);
  if (hooks.on_ready) hooks.on_ready(job.state());
  for (int pass = 0; pass < passes; ++pass) {
    if (hooks.on_pass_start) hooks.on_pass_start(pass + 1);
    if (!job.pass(cancel, hooks.on_tile_done)) return false;
    if (hooks.on_pass_done) hooks.on_pass_done(pass + 1, render_seconds(job.state()));
  }
  result = job.result();
  return true;
}

bool render_passes(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                   int passes, RenderResult& result, const std::atomic<bool>* cancel,
                   const PassDoneCallback& on_pass_done) {
  PassHooks hooks;
  hooks.on_pass_done = on_pass_done;
  return render_passes(scene, rays, settings, passes, result, cancel, hooks);
}

}  // namespace renderer
