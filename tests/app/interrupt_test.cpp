// Ctrl-C (SIGINT) and SIGTERM during a render: levrt stops, exits 130 and leaves no file behind.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace {
namespace fs = std::filesystem;

// True once the process catches SIGINT and SIGTERM (its handlers are installed), read from
// /proc/PID/status: signalling earlier would test the kernel's default action, not levrt.
bool catches_termination_signals(pid_t pid) {
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

int interrupt_render_after(int signal_number, std::chrono::milliseconds delay, const fs::path& dir) {
  const std::vector<std::string> args = {
      LEVRT_BINARY, "render", "--lights", "16384", "--method", "rt", "--width", "640", "--height", "480",
      "--spp", "4", "--out", (dir / "i.png").string(), "--stats", (dir / "s.json").string(),
      "--heatmap-lights", (dir / "l.png").string()};
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
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Interrupt, SignalDuringRenderLeavesNoOutput) {
  for (int sig : {SIGINT, SIGTERM}) {
    for (int delay_ms : {0, 600}) {  // as the scene build starts, during the render
      const fs::path dir = fs::temp_directory_path() / ("levrt_interrupt_" + std::to_string(sig) + "_" + std::to_string(delay_ms));
      fs::remove_all(dir);
      fs::create_directories(dir);
      EXPECT_EQ(interrupt_render_after(sig, std::chrono::milliseconds(delay_ms), dir), 130)
          << "signal " << sig << " after " << delay_ms << " ms";
      EXPECT_TRUE(fs::is_empty(dir)) << "signal " << sig << " after " << delay_ms << " ms";
      fs::remove_all(dir);
    }
  }
}

}  // namespace
