// levrt's entry point: runs the command line and turns failures into one line and an exit code.
// Every message is escaped here, so a newline or terminal escape in a flag value, file name or
// scene name cannot split it or drive the terminal. Running out of memory anywhere is one line
// and exit 1, never an abort: std::bad_alloc is caught at this boundary, and one that escapes a
// thread or a noexcept function (which would call std::terminate) ends the process the same way.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/settings.h"
#include "scenes/scene_file.h"

namespace {

constexpr const char* kOutOfMemory = "levrt: error: out of memory\n";

[[noreturn]] void terminate_out_of_memory_cleanly() {
  try {
    if (const std::exception_ptr current = std::current_exception())
      std::rethrow_exception(current);
  } catch (const std::bad_alloc&) {
    // Async-signal-safe output: the heap may be exhausted, and stdio may hold a lock.
    const ssize_t ignored =
        ::write(STDERR_FILENO, kOutOfMemory, std::char_traits<char>::length(kOutOfMemory));
    (void)ignored;
    std::_Exit(1);
  } catch (...) {
  }
  std::abort();
}

}  // namespace

int main(int argc, char** argv) {
  std::set_terminate(terminate_out_of_memory_cleanly);
  try {
    return app::run_cli(argc, argv);
  } catch (const app::Interrupted& e) {
    std::fprintf(stderr, "levrt: %s\n", scenes::escape_control_characters(e.what()).c_str());
    return 130;
  } catch (const app::UsageError& e) {
    std::fprintf(stderr, "levrt: %s\n", scenes::escape_control_characters(e.what()).c_str());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "levrt: %s\n", scenes::escape_control_characters(e.what()).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fputs(kOutOfMemory, stderr);
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "levrt: error: %s\n", scenes::escape_control_characters(e.what()).c_str());
    return 1;
  }
}
