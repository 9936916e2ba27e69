// The bench's monotonicity check: a tighter setting of a deterministic method must
// never make its average or maximum pixel error against rt larger. Given one method's sweep on
// one scene, loosest setting first (the order of its bench_tolerances), it lists every pair of
// settings where the tighter one erred more, for the targets experiment to print.
#pragma once

#include <string>
#include <vector>

#include "app/bench/runner.h"

namespace app::bench {

// One render of a method's sweep: the setting (tolerance or relative error) and its errors.
struct SweepPoint {
  double setting = 0.0;
  PixelErrors errors;
};

// A tighter setting that erred more than a looser one, on the average or the maximum.
struct MonotonicityViolation {
  std::string scene;  // as the tables name it, light count included
  std::string method;
  SweepPoint looser, tighter;
};

// Every (looser, tighter) pair of `loosest_first` where the tighter setting's average or maximum
// error is larger. Errors that are not numbers (unmatched pixels) are not compared.
std::vector<MonotonicityViolation> find_monotonicity_violations(
    const std::string& scene, const std::string& method,
    const std::vector<SweepPoint>& loosest_first);

// One line: "hall 16,384 lev_est: 0.0003 after 0.001: avg 0.14 % > 0.06 %, max 3.92 % > 1.05 %".
std::string violation_text(const MonotonicityViolation& violation);

}  // namespace app::bench
