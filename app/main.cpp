// levrt's entry point: runs the command line and turns failures into one line and an exit code.
#include <cstdio>
#include <exception>

#include "app/cli.h"
#include "app/interrupt.h"
#include "app/settings.h"

int main(int argc, char** argv) {
  try {
    return app::run_cli(argc, argv);
  } catch (const app::Interrupted& e) {
    std::fprintf(stderr, "levrt: %s\n", e.what());
    return 130;
  } catch (const app::UsageError& e) {
    std::fprintf(stderr, "levrt: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "levrt: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "levrt: error: %s\n", e.what());
    return 1;
  }
}
