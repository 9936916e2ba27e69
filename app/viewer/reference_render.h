// The `rt` reference of the current view, rendered on a thread of its own so that the user can
// keep trying tolerances while it runs. It renders pass by pass up to a target (the render's
// passes), one pass per resume(), so that the render worker can keep it level with the method's
// render: the error compares the two means over the same passes (display_image.h). The render
// worker owns it: it hands over a state and drops it before the camera moves; the main render
// may change method or tolerance meanwhile (render states share the scene read-only). Stopping
// keeps the finished tiles, and resuming renders the rest of the pass.
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
  // Called on the reference thread when a pass ends: complete (with the passes done so far and
  // the render time), or failed with a message. Not called when the pass is stopped.
  using PassDone = std::function<void(int passes_done, double seconds, const std::string& error)>;

  ReferenceRender(DisplayBuffer& tiles, PassDone on_pass_done);
  ~ReferenceRender();
  ReferenceRender(const ReferenceRender&) = delete;
  ReferenceRender& operator=(const ReferenceRender&) = delete;

  // Replaces the reference (stopping the previous one); tiles are posted with `generation`.
  void begin(std::unique_ptr<renderer::RenderJob> job, std::uint64_t generation);
  // The passes to render in all (at least 1); a higher target makes a complete reference go on.
  void set_target(int passes);
  // Starts (or continues) the next pass unless complete, failed, already running or without a
  // state.
  void resume();
  // Cancels the pass in flight and joins the thread; the state and its finished tiles stay.
  void stop();
  // Stops and forgets the state.
  void discard();

  bool has_state() const { return job_ != nullptr; }
  bool running() const { return running_.load(); }
  bool failed() const { return failed_.load(); }
  int passes_done() const { return passes_done_.load(); }
  int target() const { return target_.load(); }
  bool complete() const { return has_state() && passes_done() >= target(); }
  std::uint64_t generation() const { return generation_; }
  int tile_count() const;

 private:
  void run();

  DisplayBuffer& tiles_;
  PassDone on_pass_done_;
  std::unique_ptr<renderer::RenderJob> job_;
  std::uint64_t generation_ = 0;
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> running_{false};
  std::atomic<bool> failed_{false};
  std::atomic<int> passes_done_{0};
  std::atomic<int> target_{1};
};

}  // namespace app::viewer
