// Running a command from a test: the exit code and everything it printed (stdout and stderr
// together), for the tests that drive the levrt binary or a helper program through a shell.
#pragma once

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace levrt_test {

struct CommandRun {
  int exit_code = -1;  // -1 when the command could not start or did not exit normally
  std::string output;  // stdout and stderr
};

// One shell word, whatever the characters in s.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// How many lines a command printed (a one-line error is 1).
inline long line_count(const std::string& output) {
  return std::count(output.begin(), output.end(), '\n');
}

inline CommandRun run_shell(const std::string& command) {
  CommandRun run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) run.output += buffer.data();
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

#ifdef LEVRT_BINARY
// The levrt binary this build made, with each argument passed as one word.
inline CommandRun run_levrt(const std::vector<std::string>& args) {
  std::string command = LEVRT_BINARY;
  for (const std::string& a : args) command += " " + shell_quote(a);
  return run_shell(command);
}
#endif

}  // namespace levrt_test
