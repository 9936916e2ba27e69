// The experiments of `levrt bench --suite thesis`: each renders what it needs through BenchRun,
// writes its CSV and plots into the output folder, and returns its part of results.md plus its
// rows of the headline table (levrt's targets). Every experiment also runs, unchanged, in
// BenchRun's planning pass, where it renders and writes nothing.
#pragma once

#include <string>
#include <vector>

#include "app/bench/runner.h"

namespace app::bench {

struct HeadlineRow {
  std::string target;    // what is measured
  std::string goal;      // the target, e.g. ">= 300x"
  std::string thesis;    // the thesis' figure for the same thing
  std::string measured;  // ours
  std::string status;    // "met", "missed", or "n/a" (scene missing, or a --quick size)
};

struct Section {
  std::string markdown;  // starting with its "## " heading
  std::vector<HeadlineRow> headline;
};

struct ExperimentInfo {
  const char* name;    // --only value, CSV name
  const char* tables;  // which thesis tables it reproduces
  const char* summary;
  Section (*run)(BenchRun& run, const std::string& out_dir);
};

// In the order the suite runs them (later ones reuse earlier measurements).
const std::vector<ExperimentInfo>& experiments();

}  // namespace app::bench
