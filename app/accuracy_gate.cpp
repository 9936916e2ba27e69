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

std::string percent_text(double pct) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f%%", pct);
  return buffer;
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
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return gate;
}

std::optional<std::string> accuracy_gate_failure(const AccuracyGate& gate,
                                                 const renderer::PixelErrorStats& error) {
  std::string exceeded;
  if (gate.avg_pct && error.average_pct > *gate.avg_pct) {
    exceeded = "pixel error avg " + percent_text(error.average_pct) +
               " above avg=" + percent_text(*gate.avg_pct);
  }
  if (gate.max_pct && error.max_pct > *gate.max_pct) {
    exceeded += (exceeded.empty() ? "" : ", ") + std::string("pixel error max ") +
                percent_text(error.max_pct) + " above max=" + percent_text(*gate.max_pct);
  }
  if (exceeded.empty()) return std::nullopt;
  return "--fail-above: " + exceeded;
}

}  // namespace app
