// The `rt` reference of the current view, rendered on a thread of its own so that the user can
// keep trying tolerances while it runs. It renders one pass (pixel centres), which is what the
// error view compares the pass-0 image with. The render worker owns it: it hands over a state and
// drops it before the camera moves; the main render may change method or tolerance meanwhile
// (render states share the scene read-only). Stopping keeps the finished tiles, and resuming
// renders the rest.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "app/viewer/display_buffer.h"
#include "renderer/render_service.h"

namespace app::viewer {

class ReferenceRender {
 public:
  // Called on the reference thread when its pass ends: complete, or failed with a message.
  // Not called when the pass is stopped.
  using Finished = std::function<void(double seconds, const std::string& error)>;

  ReferenceRender(DisplayBuffer& tiles, Finished on_finished);
  ~ReferenceRender();
  ReferenceRender(const ReferenceRender&) = delete;
  ReferenceRender& operator=(const ReferenceRender&) = delete;

  // Replaces the reference (stopping the previous one); tiles are posted with `generation`.
  void begin(std::unique_ptr<renderer::RenderJob> job, std::uint64_t generation);
  // Starts (or continues) rendering unless complete, failed, already running or without a state.
  void resume();
  // Cancels the pass in flight and joins the thread; the state and its finished tiles stay.
  void stop();
  // Stops and forgets the state.
  void discard();

  bool has_state() const { return job_ != nullptr; }
  bool running() const { return running_.load(); }
  bool complete() const { return complete_.load(); }
  std::uint64_t generation() const { return generation_; }
  int tile_count() const;

 private:
  void run();

  DisplayBuffer& tiles_;
  Finished on_finished_;
  std::unique_ptr<renderer::RenderJob> job_;
  std::uint64_t generation_ = 0;
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> running_{false};
  std::atomic<bool> complete_{false};
  std::atomic<bool> failed_{false};
};

}  // namespace app::viewer
