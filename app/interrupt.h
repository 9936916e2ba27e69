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

// While a command works (loading the scene, rendering, tearing down after an interrupt): once
// the interrupt flag is raised and the command has not ended kLoadGraceSeconds later, the
// watchdog prints the interrupted line and ends the process with exit code 130 at once, so
// Ctrl-C ends any load within a second, even one stuck in a step that cannot poll. It never cuts
// a write short: it waits while an OutputWriteScope lives, and no write starts after it decided.
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

// One write of output files (write_output_files holds it from the first byte encoded to the last
// rename). While one lives, an InterruptWatchdog does not end the process, so a command that
// writes while it runs (the viewer's snapshots, from their own thread) can keep a watchdog for its
// whole life. A write that would begin once a watchdog has decided to end the process waits for
// that end instead: it never leaves a temporary behind.
class OutputWriteScope {
 public:
  OutputWriteScope();
  ~OutputWriteScope();
  OutputWriteScope(const OutputWriteScope&) = delete;
  OutputWriteScope& operator=(const OutputWriteScope&) = delete;
};

}  // namespace app
