// Signalling a levrt process from a test: start it, wait until it catches SIGINT and SIGTERM
// (its handlers are installed), signal it after a delay and report how it ended.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
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

// Exit code of a process that did not exit within the bound after the signal (it is then killed).
constexpr int kIgnoredSignal = 2000;

// Runs levrt with args, signals it `delay` after its handlers are installed, and returns its
// exit code (1000 + the signal when the signal killed it, so that is never mistaken for 130;
// kIgnoredSignal when it was still running `exit_bound` after the signal).
inline int interrupt_after(const std::vector<std::string>& args, int signal_number,
                           std::chrono::milliseconds delay,
                           std::chrono::milliseconds exit_bound = std::chrono::seconds(60)) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!catches_termination_signals(pid) && std::chrono::steady_clock::now() < deadline) {
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

}  // namespace levrt_test
