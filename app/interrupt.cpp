#include "app/interrupt.h"

#include <csignal>

namespace app {
namespace {

// A signal handler can reach no object but a static one: this lock-free flag is the only
// process-wide state in levrt, written by the handler and read by the render loop.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal flag must be lock-free");

void raise_flag(int) { g_interrupted.store(true); }

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

}  // namespace

InterruptScope::InterruptScope() {
  g_interrupted.store(false);
  struct sigaction action {};
  action.sa_handler = raise_flag;
  sigemptyset(&action.sa_mask);
  for (int s : kSignals) sigaction(s, &action, nullptr);
}

InterruptScope::~InterruptScope() {
  for (int s : kSignals) std::signal(s, SIG_DFL);
}

const std::atomic<bool>& InterruptScope::flag() { return g_interrupted; }

void InterruptScope::throw_if_interrupted() {
  if (g_interrupted.load()) throw Interrupted();
}

}  // namespace app
