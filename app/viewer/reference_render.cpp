#include "app/viewer/reference_render.h"

#include <algorithm>
#include <exception>
#include <utility>

namespace app::viewer {

ReferenceRender::ReferenceRender(DisplayBuffer& tiles, PassDone on_pass_done)
    : tiles_(tiles), on_pass_done_(std::move(on_pass_done)) {}

ReferenceRender::~ReferenceRender() {
  discard();
}

void ReferenceRender::begin(std::unique_ptr<renderer::RenderJob> job, std::uint64_t generation) {
  discard();
  job_ = std::move(job);
  generation_ = generation;
}

void ReferenceRender::set_target(int passes) {
  target_.store(std::max(passes, 1));
}

void ReferenceRender::resume() {
  if (!job_ || running_.load() || complete() || failed_.load()) return;
  if (thread_.joinable()) thread_.join();
  cancel_.store(false);
  running_.store(true);
  thread_ = std::thread([this] { run(); });
}

void ReferenceRender::stop() {
  cancel_.store(true);
  if (thread_.joinable()) thread_.join();
  cancel_.store(false);
}

void ReferenceRender::discard() {
  stop();
  job_.reset();
  failed_.store(false);
  passes_done_.store(0);
  generation_ = 0;
}

int ReferenceRender::tile_count() const {
  return job_ ? renderer::render_tile_count(job_->state()) : 0;
}

void ReferenceRender::run() {
  renderer::RenderState& state = job_->state();
  const renderer::Framebuffer& framebuffer = renderer::render_framebuffer(state);
  const std::uint64_t generation = generation_;
  const int pass = renderer::render_passes_done(state);
  const auto on_tile_done = [&](int tile) {
    TileRect r;
    renderer::render_tile_rect(state, tile, r.x0, r.y0, r.x1, r.y1);
    tiles_.post(copy_tile(framebuffer, generation, tile, pass, r));
  };
  std::string error;
  bool done = false;
  try {
    done = job_->pass(&cancel_, on_tile_done);
  } catch (const std::exception& e) {
    error = e.what();
  }
  const double seconds = renderer::render_seconds(state);
  const int passes = renderer::render_passes_done(state);
  passes_done_.store(passes);
  if (!error.empty()) failed_.store(true);
  running_.store(false);
  if (done || !error.empty()) on_pass_done_(passes, seconds, error);
}

}  // namespace app::viewer
