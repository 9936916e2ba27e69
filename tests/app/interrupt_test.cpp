// Ctrl-C (SIGINT) and SIGTERM during a render: levrt stops, exits 130 and leaves no file behind.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace {
namespace fs = std::filesystem;

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
  std::this_thread::sleep_for(delay);
  kill(pid, signal_number);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Interrupt, SignalDuringRenderLeavesNoOutput) {
  for (int sig : {SIGINT, SIGTERM}) {
    for (int delay_ms : {50, 600}) {  // during the scene build, during the render
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
