// The interrupt watchdog (app/interrupt.h) against writes in flight: past its grace it ends the
// process with 130, but never while an OutputWriteScope lives, so a command may keep a watchdog
// for its whole life (the viewer does) and still never leave a half-written file. Each case runs
// in a forked child, since the watchdog ends its process.
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
using Clock = std::chrono::steady_clock;

struct ChildEnd {
  int exit_code = -1;  // -1: it did not exit normally
  double seconds = 0.0;
};

// Runs body in a forked child that then sleeps far past any grace; returns how the child ended.
template <typename Body>
ChildEnd run_child(Body body) {
  const auto start = Clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    std::this_thread::sleep_for(std::chrono::seconds(20));
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ChildEnd end;
  end.seconds = std::chrono::duration<double>(Clock::now() - start).count();
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
  EXPECT_GE(end.seconds, app::kLoadGraceSeconds);
}

// The signal comes while another thread writes: the write completes (its file is whole), then
// the watchdog ends the process, not before.
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
  EXPECT_GE(end.seconds, kWriteSeconds);
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

}  // namespace
