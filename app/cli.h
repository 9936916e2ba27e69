// The levrt command line: subcommands, flags generated from the settings table, and the mapping
// of errors to exit codes (2 for usage, 1 for internal failures).
#pragma once

namespace app {

int run_cli(int argc, char** argv);

}  // namespace app
