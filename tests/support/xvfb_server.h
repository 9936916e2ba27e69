// A private Xvfb server for the viewer tests, started directly rather than through xvfb-run:
// xvfb-run, when its client exits at once, sometimes fails to remove its own temporary folder
// and exits 5, hiding the viewer's exit code; and a test that signals the viewer must reach
// the levrt process, not xvfb-run's shell. -displayfd lets Xvfb pick a free display.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "tests/support/run_command.h"

namespace levrt_test {

inline bool have_xvfb() {
  return std::system("command -v Xvfb > /dev/null 2>&1") == 0;
}

class XvfbServer {
 public:
  explicit XvfbServer(const std::string& screen = "1280x800x24") {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      // The server dies with the test process even when its destructor never runs (an abort, a
      // ctest timeout), and never holds ctest's output pipe open.
      ::prctl(PR_SET_PDEATHSIG, SIGTERM);
      ::dup2(fds[1], STDOUT_FILENO);
      const int null_fd = ::open("/dev/null", O_WRONLY);
      if (null_fd >= 0) ::dup2(null_fd, STDERR_FILENO);
      ::close(fds[0]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", "1", "-screen", "0", screen.c_str(), "-nolisten",
               "tcp", static_cast<char*>(nullptr));
      _exit(127);
    }
    ::close(fds[1]);
    std::string number;
    char c = 0;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~XvfbServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;
  // Empty when the server did not start.
  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

#ifdef LEVRT_BINARY
// `levrt view ARGS` on the display of a server started for this process, with its exit code.
// Mesa's GL driver is unloaded before LeakSanitizer runs at exit, so its one-off allocations
// show up as leaks of an unknown module: under the asan preset the windowed process runs with
// leak checking off (its other checks stay on; the worker tests check leaks in-process).
inline CommandRun run_viewer_on_xvfb(const std::vector<std::string>& args) {
  static const XvfbServer server;
  if (server.display().empty()) return {-1, "Xvfb did not start"};
  std::string command = "DISPLAY=" + server.display() +
                        " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " +
                        shell_quote(LEVRT_BINARY) + " view";
  for (const std::string& a : args) command += " " + shell_quote(a);
  return run_shell(command);
}
#endif

}  // namespace levrt_test
