#include "app/interrupt.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <string>

namespace app {
namespace {

// A signal handler can reach no object but a static one: this lock-free flag is the only
// process-wide state in levrt, written by the handler and read by the render loop.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal flag must be lock-free");

void raise_flag(int) {
  g_interrupted.store(true);
}

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

const std::atomic<bool>& InterruptScope::flag() {
  return g_interrupted;
}

void InterruptScope::throw_if_interrupted() {
  if (g_interrupted.load()) throw Interrupted();
}

InterruptWatchdog::InterruptWatchdog() {
  thread_ = std::thread([this] {
    using Clock = std::chrono::steady_clock;
    constexpr auto kPoll = std::chrono::milliseconds(20);
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_ && !g_interrupted.load()) ended_.wait_for(lock, kPoll);
    if (done_) return;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(kLoadGraceSeconds));
    if (ended_.wait_until(lock, deadline, [this] { return done_; })) return;
    // The command is stuck in a step that cannot poll, or slow to tear down. It has written
    // nothing; nothing else may run (no destructor, no other thread's half-done state): one
    // line, then _Exit.
    const std::string line = std::string("levrt: ") + Interrupted().what() + "\n";
    const ssize_t ignored = ::write(STDERR_FILENO, line.data(), line.size());
    (void)ignored;
    std::_Exit(130);
  });
}

InterruptWatchdog::~InterruptWatchdog() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  ended_.notify_all();
  thread_.join();
}

}  // namespace app
