// Ctrl-C and termination requests for the headless commands. While an InterruptScope lives,
// SIGINT, SIGTERM and SIGHUP only raise a flag that the render loop polls as its cancel flag; the
// command then stops between tiles, writes nothing, and exits with 130. (Output files are written
// to a temporary name and renamed with these signals blocked, so no signal can leave a partial
// file either.)
#pragma once

#include <atomic>
#include <stdexcept>

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

}  // namespace app
