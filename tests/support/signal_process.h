// Signalling a levrt process from a test: start it, wait until it catches SIGINT and SIGTERM
// (its handlers are installed), signal it after a delay and report how it ended: its exit code
// and the stage its interrupted line names (app/interrupt.h: "loading the scene, step 3 of 3",
// "rendering rt, pass 1 of 4, 12 of 300 tiles done"). Tests tell a command that stopped at the
// signal from one that finished its work first by that stage, never by the time it took; the
// only clock here is a hang guard of minutes that fails the test.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

namespace levrt_test {

// True once the process catches SIGINT and SIGTERM (its handlers are installed), read from
// /proc/PID/status: signalling earlier would test the kernel's default action, not levrt.
inline bool catches_termination_signals(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("SigCgt:", 0) == 0) {
      const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
      const unsigned long long wanted = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
      return (mask & wanted) == wanted;
    }
  }
  return false;
}

// True once the process has read at least `bytes` through read calls (/proc/PID/io's rchar): a
// test that signals a load waits until the scene's buffer is in, so the signal finds the process
// in the load's steps after it (building the geometry), not still starting up.
inline bool has_read_at_least(pid_t pid, unsigned long long bytes) {
  std::ifstream io("/proc/" + std::to_string(pid) + "/io");
  std::string line;
  while (std::getline(io, line)) {
    if (line.rfind("rchar:", 0) == 0) return std::stoull(line.substr(6)) >= bytes;
  }
  return false;
}

// What a test waits for, beyond the handlers, before it signals the process (null: nothing).
using ReadyToSignal = std::function<bool(pid_t)>;

// Exit code of a process that did not exit within the bound after the signal (it is then killed).
constexpr int kIgnoredSignal = 2000;

// Runs levrt with args, signals it `delay` after its handlers are installed (and `ready` holds,
// when given; the signal goes anyway after 30 s, and the test's check of the stage fails), and
// returns its
// exit code (1000 + the signal when the signal killed it, so that is never mistaken for 130;
// kIgnoredSignal when it was still running `exit_bound` after the signal). errors_fd, when not
// -1, becomes the process' standard error.
inline int interrupt_after(const std::vector<std::string>& args, int signal_number,
                           std::chrono::milliseconds delay,
                           std::chrono::milliseconds exit_bound = std::chrono::seconds(60),
                           int errors_fd = -1, const ReadyToSignal& ready = nullptr) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (errors_fd != -1) dup2(errors_fd, STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!(catches_termination_signals(pid) && (!ready || ready(pid))) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::this_thread::sleep_for(delay);
  kill(pid, signal_number);
  const auto exit_deadline = std::chrono::steady_clock::now() + exit_bound;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > exit_deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return kIgnoredSignal;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// A levrt process that does not end within this after the signal hangs: it is killed and the
// test fails. Generous (a loaded machine, a sanitizer build): it measures nothing.
constexpr std::chrono::minutes kInterruptHangGuard{3};

// How an interrupted levrt ended: its exit code (as interrupt_after's) and its standard error.
struct InterruptedRun {
  int exit_code = 0;
  std::string errors;
};

// As interrupt_after, with the process' standard error kept (in an unnamed temporary file, so a
// chatty process never blocks on a pipe) and kInterruptHangGuard as the bound.
inline InterruptedRun interrupt_and_read(const std::vector<std::string>& args, int signal_number,
                                         std::chrono::milliseconds delay,
                                         const ReadyToSignal& ready = nullptr) {
  InterruptedRun run;
  std::FILE* errors = std::tmpfile();
  if (!errors) {
    run.exit_code = -1;
    run.errors = "the test could not make a temporary file for the standard error";
    return run;
  }
  run.exit_code =
      interrupt_after(args, signal_number, delay, kInterruptHangGuard, ::fileno(errors), ready);
  std::rewind(errors);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, errors)) > 0;)
    run.errors.append(buffer, n);
  std::fclose(errors);
  return run;
}

// The stage an interrupted line names, parsed: "levrt: interrupted while DOING[, WORD STEP of
// STEPS][: DETAIL][, TILES_DONE of TILES tiles done]; no output written".
struct InterruptedStage {
  bool found = false;  // the process printed an interrupted line
  std::string doing;   // "" when it named no stage
  int step = 0, steps = 0;
  int tiles_done = 0, tiles = 0;
};

inline InterruptedStage interrupted_stage(const std::string& errors) {
  static const std::regex line(
      R"(levrt: interrupted(?: while ([^;]*?)(?:, (?:step|pass) (\d+) of (\d+))?(?:: [^;]*?)?)"
      R"((?:, (\d+) of (\d+) tiles done)?)?; no output written)");
  InterruptedStage stage;
  std::smatch m;
  if (!std::regex_search(errors, m, line)) return stage;
  stage.found = true;
  stage.doing = m[1];
  const auto number = [&m](int i) { return m[i].matched ? std::stoi(m[i]) : 0; };
  stage.step = number(2);
  stage.steps = number(3);
  stage.tiles_done = number(4);
  stage.tiles = number(5);
  return stage;
}

// For a test's one-line check: what an interrupted levrt was doing when it stopped ("loading the
// scene", "rendering rt") when it exited 130 with an interrupted line, else how it ended instead.
inline std::string interrupted_while(const std::vector<std::string>& args, int signal_number,
                                     std::chrono::milliseconds delay,
                                     const ReadyToSignal& ready = nullptr) {
  const InterruptedRun run = interrupt_and_read(args, signal_number, delay, ready);
  const InterruptedStage stage = interrupted_stage(run.errors);
  if (run.exit_code == 130 && stage.found) return stage.doing;
  return "exit " + std::to_string(run.exit_code) + ", standard error: " + run.errors;
}

}  // namespace levrt_test
