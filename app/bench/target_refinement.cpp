#include "app/bench/target_refinement.h"

#include <cmath>

namespace app::bench {

double setting_between(double looser, double tighter) {
  if (!(looser > 0.0) || !(tighter > 0.0)) return 0.0;
  const double mean = std::sqrt(looser * tighter);
  // Two significant digits: the decade's step is 1/10 of the leading digit's place.
  const double step = std::pow(10.0, std::floor(std::log10(mean)) - 1.0);
  return std::round(mean / step) * step;
}

std::vector<SettingToTry> settings_to_try(const std::vector<SettingResult>& renders) {
  double best_speedup = 0.0;
  for (const SettingResult& r : renders) {
    if (r.meets && r.speedup > best_speedup) best_speedup = r.speedup;
  }
  std::vector<SettingToTry> out;
  std::vector<const lev::MethodInfo*> seen;
  for (const SettingResult& first : renders) {
    const lev::MethodInfo* method = first.method;
    if (!method || !(method->uses_tolerance || method->uses_relative_error)) continue;
    bool done = false;
    for (const lev::MethodInfo* m : seen) done = done || m == method;
    if (done) continue;
    seen.push_back(method);
    // The method's fastest render that meets the target, and the next looser render.
    const SettingResult* fastest = nullptr;
    for (const SettingResult& r : renders) {
      if (r.method == method && r.meets && (!fastest || r.speedup > fastest->speedup)) fastest = &r;
    }
    if (!fastest) continue;
    const SettingResult* looser = nullptr;
    for (const SettingResult& r : renders) {
      if (r.method == method && r.setting > fastest->setting &&
          (!looser || r.setting < looser->setting)) {
        looser = &r;
      }
    }
    if (!looser || looser->meets || !(looser->speedup > best_speedup)) continue;
    const double between = setting_between(looser->setting, fastest->setting);
    if (!(between > fastest->setting && between < looser->setting)) continue;
    bool rendered = false;
    for (const SettingResult& r : renders) {
      rendered = rendered || (r.method == method && r.setting == between);
    }
    if (!rendered) out.push_back({method, between});
  }
  return out;
}

}  // namespace app::bench
