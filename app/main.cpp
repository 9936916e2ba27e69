// levrt's entry point: runs the command line and turns failures into one line and an exit code.
// Every message is escaped here, so a newline or terminal escape in a flag value, file name or
// scene name cannot split it or drive the terminal.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/settings.h"
#include "scenes/scene_file.h"

namespace {

// An exception escaping where none may (a noexcept function, a thread of a library), most likely
// std::bad_alloc under a memory limit: one line and exit 1, as main's own handler gives, rather
// than abort's two lines and exit 134.
[[noreturn]] void exit_on_uncaught_exception() {
  std::string what = "an exception escaped";
  try {
    if (const std::exception_ptr escaped = std::current_exception())
      std::rethrow_exception(escaped);
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  std::fprintf(stderr, "levrt: error: %s\n", scenes::escape_control_characters(what).c_str());
  std::_Exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  std::set_terminate(exit_on_uncaught_exception);
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
  } catch (const std::exception& e) {
    std::fprintf(stderr, "levrt: error: %s\n", scenes::escape_control_characters(e.what()).c_str());
    return 1;
  }
}
