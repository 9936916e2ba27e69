#include "app/interrupt.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <string>
#include <utility>

namespace app {
namespace {

// A signal handler can reach no object but a static one: this lock-free flag is written by the
// handler and read by the render loop. It and the writes in flight below are levrt's only
// process-wide state: the watchdog that ends the process must see every writer, whatever thread
// or command layer it runs in.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal flag must be lock-free");

struct WritesInFlight {
  std::mutex mutex;
  std::condition_variable changed;
  int count = 0;
  bool ending = false;  // a watchdog is ending the process: no write may begin
};
WritesInFlight g_writes;

// Marks the process as ending when no write is in flight; false while one is.
bool end_unless_writing() {
  const std::lock_guard<std::mutex> lock(g_writes.mutex);
  if (g_writes.count > 0) return false;
  g_writes.ending = true;
  return true;
}

// The stage the command is in (CommandStage), for the interrupted line.
struct NotedStage {
  std::mutex mutex;
  StageNote note;
};
NotedStage g_stage;
std::atomic<int> g_tiles_done{0};

void note_stage(const StageNote& note, int tiles_done) {
  const std::lock_guard<std::mutex> lock(g_stage.mutex);
  g_stage.note = note;
  g_tiles_done.store(tiles_done);
}

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

CommandStage::CommandStage(StageNote note)
    : note_(std::move(note)), exceptions_(std::uncaught_exceptions()) {
  const std::lock_guard<std::mutex> lock(g_stage.mutex);
  before_ = g_stage.note;
  before_tiles_done_ = g_tiles_done.load();
  g_stage.note = note_;
  g_tiles_done.store(0);
}

CommandStage::~CommandStage() {
  if (std::uncaught_exceptions() > exceptions_ && g_interrupted.load()) return;
  note_stage(before_, before_tiles_done_);
}

void CommandStage::step(int step, const std::string& detail) {
  note_.step = step;
  note_.detail = detail;
  note_stage(note_, 0);
}

void CommandStage::count_tiles(int tiles) {
  note_.tiles = tiles;
  note_stage(note_, 0);
}

void note_tile_done() {
  g_tiles_done.fetch_add(1);
}

std::string interrupted_message() {
  StageNote note;
  int tiles_done = 0;
  {
    const std::lock_guard<std::mutex> lock(g_stage.mutex);
    note = g_stage.note;
    tiles_done = g_tiles_done.load();
  }
  std::string where;
  if (!note.doing.empty()) {
    where = " while " + note.doing;
    if (note.steps > 0) {
      where += ", " + note.step_word + " " + std::to_string(note.step) + " of " +
               std::to_string(note.steps);
    }
    if (!note.detail.empty()) where += ": " + note.detail;
    if (note.tiles > 0) {
      where +=
          ", " + std::to_string(tiles_done) + " of " + std::to_string(note.tiles) + " tiles done";
    }
  }
  return "interrupted" + where + "; no output written";
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
    // Past the grace, but a write in flight finishes first (its files complete and renamed).
    while (!end_unless_writing()) {
      if (ended_.wait_for(lock, kPoll, [this] { return done_; })) return;
    }
    // The command is stuck in a step that cannot poll, or slow to tear down. It has written
    // nothing; nothing else may run (no destructor, no other thread's half-done state): one
    // line, then _Exit.
    const std::string line = "levrt: " + interrupted_message() + "\n";
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

OutputWriteScope::OutputWriteScope() {
  std::unique_lock<std::mutex> lock(g_writes.mutex);
  // Once ending, the watchdog's _Exit follows at once: waiting for it writes nothing.
  g_writes.changed.wait(lock, [] { return !g_writes.ending; });
  g_writes.count += 1;
}

OutputWriteScope::~OutputWriteScope() {
  {
    const std::lock_guard<std::mutex> lock(g_writes.mutex);
    g_writes.count -= 1;
  }
  g_writes.changed.notify_all();
}

}  // namespace app
