// The targets experiment's search between grid settings. Each method is swept over a coarse grid
// (its bench_tolerances, half a decade apart), so the fastest setting that meets an error target
// can lie between a grid setting that meets it and the next looser one that misses it. Where that
// looser setting was faster than the best render meeting the target so far, the setting between
// the two (their geometric mean, to two significant digits) is worth a render; the experiment
// renders it, in turns with rt, and asks again, a few rounds deep. A looser setting that was
// not faster than the best cannot lead to a better one, as a method's time grows as its setting
// tightens, so the search stays small: a few renders per scene.
#pragma once

#include <vector>

#include "lev/methods.h"

namespace app::bench {

// One render of a sweep, as the search reads it against one error target.
struct SettingResult {
  const lev::MethodInfo* method = nullptr;
  double setting = 0.0;  // tolerance or relative error
  double speedup = 0.0;  // over rt, timed in turns with it
  bool meets = false;    // the target at hand
};

// A setting to render next.
struct SettingToTry {
  const lev::MethodInfo* method = nullptr;
  double setting = 0.0;
};

// The geometric mean of two settings, rounded to two significant digits (a value a user can
// type); 0 where a setting is not positive.
double setting_between(double looser, double tighter);

// For one error target: per method swept over a setting (uses_tolerance or uses_relative_error),
// the setting between its fastest render that meets the target and the next looser render,
// where that looser one misses the target, was faster than every render meeting it (any
// method's), and the setting between is not rendered yet and lies strictly between the two.
std::vector<SettingToTry> settings_to_try(const std::vector<SettingResult>& renders);

}  // namespace app::bench
