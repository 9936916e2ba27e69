// The interrupt watchdog (app/interrupt.h) against writes in flight: past its grace it ends the
// process with 130, but never while an OutputWriteScope lives, so a command may keep a watchdog
// for its whole life (the viewer does) and still never leave a half-written file. Each case runs
// in a forked child, since the watchdog ends its process. The stage the interrupted line names
// (CommandStage) is checked in-process.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "app/interrupt.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;

struct ChildEnd {
  int exit_code = -1;  // -1: it did not exit normally
};

// Runs body in a forked child that then sleeps far past any grace; returns how the child ended.
template <typename Body>
ChildEnd run_child(Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    std::this_thread::sleep_for(std::chrono::seconds(20));
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ChildEnd end;
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  return end;
}

constexpr double kWriteSeconds = 3 * app::kLoadGraceSeconds;

TEST(InterruptWatchdog, EndsTheProcessAfterItsGraceWhenNothingIsWritten) {
  const ChildEnd end = run_child([] {
    const app::InterruptScope scope;
    const app::InterruptWatchdog watchdog;
    ::kill(::getpid(), SIGTERM);
    std::this_thread::sleep_for(std::chrono::seconds(20));
  });
  EXPECT_EQ(end.exit_code, 130);
}

// The signal comes while another thread writes for three graces: the write completes (its file is
// whole, which is how the test tells the watchdog waited), then the watchdog ends the process.
TEST(InterruptWatchdog, WaitsForAWriteInFlightThenEnds) {
  const levrt_test::TempDir temp("levrt_watchdog_write_");
  const fs::path written = temp.path() / "written";
  const ChildEnd end = run_child([&written] {
    const app::InterruptScope scope;
    const app::InterruptWatchdog watchdog;
    std::thread writer([&written] {
      const app::OutputWriteScope writing;
      ::kill(::getpid(), SIGTERM);
      std::this_thread::sleep_for(std::chrono::duration<double>(kWriteSeconds));
      std::ofstream(written) << "whole";
    });
    writer.join();
    std::this_thread::sleep_for(std::chrono::seconds(20));
  });
  EXPECT_EQ(end.exit_code, 130);
  std::ifstream in(written);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "whole");
}

// Without a signal the watchdog never ends anything, writes or not.
TEST(InterruptWatchdog, WithoutASignalTheCommandEndsAsItWants) {
  const ChildEnd end = run_child([] {
    const app::InterruptScope scope;
    {
      const app::InterruptWatchdog watchdog;
      const app::OutputWriteScope writing;
      std::this_thread::sleep_for(std::chrono::duration<double>(kWriteSeconds));
    }
    ::_exit(7);
  });
  EXPECT_EQ(end.exit_code, 7);
}

// The interrupted line names the stage in progress and its counts; a stage left normally gives
// the line back to the one before it, and one left by an exception after the signal keeps it (the
// line is made after the unwinding, and that stage is where the command stopped).
TEST(CommandStage, TheInterruptedLineNamesWhereTheCommandStopped) {
  EXPECT_EQ(app::interrupted_message(), "interrupted; no output written");
  {
    const app::CommandStage outer("testing");
    {
      app::CommandStage load({"loading the scene", "step", 1, 3, "reading the scene file"});
      load.step(2, "instantiating it");
      EXPECT_EQ(app::interrupted_message(),
                "interrupted while loading the scene, step 2 of 3: instantiating it; no output "
                "written");
    }
    EXPECT_EQ(app::interrupted_message(), "interrupted while testing; no output written");
    {
      app::CommandStage render({"rendering lev", "pass", 1, 4, "setting up the method"});
      render.count_tiles(10);
      render.step(2);
      app::note_tile_done();
      app::note_tile_done();
      EXPECT_EQ(app::interrupted_message(),
                "interrupted while rendering lev, pass 2 of 4, 2 of 10 tiles done; no output "
                "written");
    }
    const app::InterruptScope interrupts;
    ::raise(SIGINT);
    try {
      const app::CommandStage load({"loading the scene", "step", 3, 3, "building"});
      throw app::Interrupted();
    } catch (const app::Interrupted& e) {
      EXPECT_EQ(std::string(e.what()),
                "interrupted while loading the scene, step 3 of 3: building; no output written");
    }
    EXPECT_EQ(app::interrupted_message(),
              "interrupted while loading the scene, step 3 of 3: building; no output written");
  }
  { const app::InterruptScope lowers_the_flag_for_the_tests_after_this_one; }
  EXPECT_EQ(app::interrupted_message(), "interrupted; no output written");
}

}  // namespace
