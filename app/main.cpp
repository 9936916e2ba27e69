// levrt's entry point: runs the command line and turns failures into one line and an exit code.
// Every message is escaped here, so a newline or terminal escape in a flag value, file name or
// scene name cannot split it or drive the terminal.
#include <cstdio>
#include <exception>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/settings.h"
#include "scenes/scene_file.h"

int main(int argc, char** argv) {
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
