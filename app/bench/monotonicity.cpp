#include "app/bench/monotonicity.h"

#include <cstdio>

#include "app/bench/experiment_support.h"

namespace app::bench {

std::vector<MonotonicityViolation> find_monotonicity_violations(
    const std::string& scene, const std::string& method,
    const std::vector<SweepPoint>& loosest_first) {
  std::vector<MonotonicityViolation> violations;
  for (std::size_t t = 1; t < loosest_first.size(); ++t) {
    const PixelErrors& tight = loosest_first[t].errors;
    for (std::size_t l = 0; l < t; ++l) {
      const PixelErrors& loose = loosest_first[l].errors;
      // NaN compares false: an unmatched render is no violation.
      if (tight.average_pct > loose.average_pct || tight.max_pct > loose.max_pct) {
        violations.push_back({scene, method, loosest_first[l], loosest_first[t]});
      }
    }
  }
  return violations;
}

std::string violation_text(const MonotonicityViolation& v) {
  const auto pct = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", value);
    return std::string(text);
  };
  std::string text = v.scene + " " + v.method + ": " + tolerance_text(v.tighter.setting) +
                     " after " + tolerance_text(v.looser.setting) + ":";
  const char* separator = " ";
  if (v.tighter.errors.average_pct > v.looser.errors.average_pct) {
    text += separator + std::string("avg ") + pct(v.tighter.errors.average_pct) + " > " +
            pct(v.looser.errors.average_pct);
    separator = ", ";
  }
  if (v.tighter.errors.max_pct > v.looser.errors.max_pct) {
    text += separator + std::string("max ") + pct(v.tighter.errors.max_pct) + " > " +
            pct(v.looser.errors.max_pct);
  }
  return text;
}

}  // namespace app::bench
