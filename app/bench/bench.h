// `levrt bench`: the thesis' experiments (chapter 5, Appendix B Tables 1-15) reproduced on the
// built-in scene models, plus two of levrt's own (the speed/accuracy trade and the distance to
// Embree's ray-casting limit). Writes DIR/results.md, one CSV per experiment and PNG plots;
// progress and an estimate of the time left go to stderr.
//
//   levrt bench --suite thesis --out DIR [--quick] [--only NAME[,NAME]] [--threads N]
//
// --quick runs the same harness at small sizes (for CI: it checks the files, not the figures).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct BenchFlags {
  std::string suite = "thesis";
  std::string out;
  bool quick = false;
  std::string only;
  std::string threads;
  std::string scenes;
  // Whether the flag was given at all (an empty value is an error, an absent flag the default).
  bool only_given = false;
  bool threads_given = false;
  bool scenes_given = false;
};

// Registers the flags on the `bench` subcommand.
void add_bench_flags(CLI::App& command, BenchFlags& flags);

// Validates the flags (UsageError, before anything is written), runs the suite, returns 0.
int run_bench(const BenchFlags& flags);

// The experiment names --only accepts, in the order the suite runs them.
std::vector<std::string> bench_experiment_names();

}  // namespace app
