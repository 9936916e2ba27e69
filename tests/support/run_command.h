// Running a command from a test: the exit code and everything it printed (stdout and stderr
// together), for the tests that drive the levrt binary or a helper program through a shell.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
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

// Runs the levrt binary with `args` and its standard output a pipe whose reader has gone (as in
// `levrt ... | true`), its standard error written to `messages_path`, and SIGPIPE at its default
// as a shell starts it, whatever this test process does. Returns the wait status.
inline int run_levrt_into_closed_pipe(const std::vector<std::string>& args,
                                      const std::string& messages_path) {
  std::vector<std::string> words = {LEVRT_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int ends[2];
  if (::pipe(ends) != 0) return -1;
  ::close(ends[0]);
  const pid_t child = ::fork();
  if (child < 0) return -1;
  if (child == 0) {
    std::signal(SIGPIPE, SIG_DFL);
    ::dup2(ends[1], STDOUT_FILENO);
    const int err = ::open(messages_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(err, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(ends[1]);
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return -1;
  return status;
}
#endif

}  // namespace levrt_test
