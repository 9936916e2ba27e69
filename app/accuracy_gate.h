// `levrt render --fail-above avg=A,max=M`: a CI job's gate on accuracy. The render's pixel error
// against the rt reference (pixel_error.h, percent of 765) is compared with the limits given; a
// render above either makes `levrt render` exit 3 with one line, after writing its outputs, so
// the job keeps the images that show where it failed.
#pragma once

#include <optional>
#include <string>

#include "renderer/pixel_error.h"

namespace app {

// The exit code of a render whose error exceeds a --fail-above limit.
inline constexpr int kAccuracyGateExitCode = 3;

struct AccuracyGate {
  std::optional<double> avg_pct;  // the largest pixel_error_avg_pct that passes
  std::optional<double> max_pct;  // the largest pixel_error_max_pct that passes
  // Each limit as typed, for the message (a double prints 0.00001 as 0.0000 at four places).
  std::string avg_text, max_text;
};

// Parses "avg=A,max=M", "avg=A" or "max=M" (percent, finite, >= 0; each key once). Throws
// UsageError "--fail-above: ..., got 'text'".
AccuracyGate parse_accuracy_gate(const std::string& text);

// The one line saying which limit the error exceeds, or nothing when it passes.
std::optional<std::string> accuracy_gate_failure(const AccuracyGate& gate,
                                                 const renderer::PixelErrorStats& error);

}  // namespace app
