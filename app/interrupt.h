// Ctrl-C and termination requests for the commands. While an InterruptScope lives, SIGINT,
// SIGTERM and SIGHUP only raise a flag that the render loop polls as its cancel flag, and the
// scene load between its steps (app/scene_loading.h); the command then stops, writes nothing,
// and exits with 130. (Output files are written to temporaries and renamed with these signals
// blocked, so no signal can leave a partial file either.) A load step that cannot poll (parsing
// a large glTF, a read blocked in the kernel) is bounded by an InterruptWatchdog.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace app {

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted; no output written") {}
};

class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // The flag the signal handler raises; pass it to render_pass as the cancel flag.
  static const std::atomic<bool>& flag();
  static void throw_if_interrupted();
};

// While a command works without writing (loading the scene, rendering, tearing down after an
// interrupt): once the interrupt flag is raised and the command has not ended kLoadGraceSeconds
// later, the watchdog prints the interrupted line and ends the process with exit code 130 at
// once, so Ctrl-C ends any load within a second, even one stuck in a step that cannot poll.
// Destroy it before writing outputs: a write is never cut short.
inline constexpr double kLoadGraceSeconds = 0.5;

class InterruptWatchdog {
 public:
  InterruptWatchdog();
  ~InterruptWatchdog();  // stops the watchdog
  InterruptWatchdog(const InterruptWatchdog&) = delete;
  InterruptWatchdog& operator=(const InterruptWatchdog&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable ended_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace app
