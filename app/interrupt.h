// Ctrl-C and termination requests for the commands. While an InterruptScope lives, SIGINT,
// SIGTERM and SIGHUP only raise a flag that the render loop polls as its cancel flag, and the
// scene load between its steps (app/scene_loading.h); the command then stops, writes nothing,
// and exits with 130. (Output files are written to temporaries and renamed with these signals
// blocked, so no signal can leave a partial file either.) A load step that cannot poll (parsing
// a large glTF, a read blocked in the kernel) is bounded by an InterruptWatchdog. The line an
// interrupt ends with names the stage the command stopped in (CommandStage), so the user, and a
// test, can tell where it stopped by what it had done, not by how long it took.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace app {

// What a command is doing, for the interrupted line: "loading the scene" (step 2 of 3:
// instantiating it), "choosing the exposure", "rendering lev" (pass 2 of 4, with the pass's tiles
// done of its tiles), "finishing after the last pass". One stage is noted per process, by the
// thread that does the command's work; the watchdog reads it from its own thread.
struct StageNote {
  std::string doing;               // "loading the scene", "rendering lev"
  std::string step_word = "step";  // "pass" for a render
  int step = 0;                    // the step in progress, from 1; 0: no steps
  int steps = 0;                   // of how many
  std::string detail;              // what the step does ("building the ray-tracing structures")
  int tiles = 0;  // a render pass's tiles (0: no tile count); note_tile_done counts them
};

// Notes a stage while it lives (nested scopes stack). Left normally it restores the stage before
// it; left by an exception once the interrupt flag is raised it keeps its own, since that is where
// the command stopped and the interrupted line is made after the unwinding.
class CommandStage {
 public:
  explicit CommandStage(StageNote note);
  explicit CommandStage(const char* doing) : CommandStage(StageNote{doing, "step", 0, 0, "", 0}) {}
  ~CommandStage();
  CommandStage(const CommandStage&) = delete;
  CommandStage& operator=(const CommandStage&) = delete;

  // The next step of this stage (its tiles done start again from 0).
  void step(int step, const std::string& detail = std::string());
  // From now on each step has this many tiles (note_tile_done counts them).
  void count_tiles(int tiles);

 private:
  StageNote note_;
  StageNote before_;
  int before_tiles_done_ = 0;
  int exceptions_ = 0;
};

// A tile of the current render pass is done (any thread).
void note_tile_done();

// "interrupted while loading the scene, step 3 of 3: building its ray-tracing structures; no
// output written", "interrupted while rendering lev, pass 2 of 4, 37 of 300 tiles done; no output
// written", or "interrupted; no output written" when no stage is noted.
std::string interrupted_message();

struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error(interrupted_message()) {}
  // A command that wrote files before the signal (the viewer's screenshots and snapshots) says
  // which, in place of "no output written".
  explicit Interrupted(const std::string& message) : std::runtime_error(message) {}
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
