#include "app/accuracy_gate.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "app/settings.h"

namespace app {
namespace {

[[noreturn]] void reject(const std::string& what, const std::string& text) {
  throw UsageError("--fail-above: " + what + ", got '" + text + "'");
}

double parse_limit_pct(const std::string& key, const std::string& value, const std::string& text) {
  const std::string what = key + " must be a finite decimal number of percent >= 0";
  if (!is_decimal_real(value)) reject(what, text);
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v) || v < 0.0) reject(what, text);
  return v;
}

// The error, at four decimal places unless they round it to the limit or below it: then with as
// many significant digits as it takes to show it above (at most 17, which round-trip a double).
std::string error_above_text(double pct, double limit) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f", pct);
  for (int digits = 6; std::strtod(buffer, nullptr) <= limit && digits <= 17; ++digits)
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, pct);
  return std::string(buffer) + "%";
}

}  // namespace

AccuracyGate parse_accuracy_gate(const std::string& text) {
  const std::string form = "must be avg=A,max=M (either or both, in percent)";
  AccuracyGate gate;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos) reject(form, text);
    const std::string key = item.substr(0, equals);
    const std::string value = item.substr(equals + 1);
    std::optional<double>* limit = key == "avg"   ? &gate.avg_pct
                                   : key == "max" ? &gate.max_pct
                                                  : nullptr;
    if (!limit) reject(form, text);
    if (limit->has_value()) reject(key + " is given twice", text);
    *limit = parse_limit_pct(key, value, text);
    (key == "avg" ? gate.avg_text : gate.max_text) = value;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return gate;
}

std::optional<std::string> accuracy_gate_failure(const AccuracyGate& gate,
                                                 const renderer::PixelErrorStats& error) {
  std::string exceeded;
  if (gate.avg_pct && error.average_pct > *gate.avg_pct) {
    exceeded = "pixel error avg " + error_above_text(error.average_pct, *gate.avg_pct) +
               " above avg=" + gate.avg_text + "%";
  }
  if (gate.max_pct && error.max_pct > *gate.max_pct) {
    exceeded += (exceeded.empty() ? "" : ", ") + std::string("pixel error max ") +
                error_above_text(error.max_pct, *gate.max_pct) + " above max=" + gate.max_text +
                "%";
  }
  if (exceeded.empty()) return std::nullopt;
  return "--fail-above: " + exceeded;
}

}  // namespace app
