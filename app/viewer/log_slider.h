// The tolerance slider's mapping between a slider position and a value. The slider is a plain
// float slider over log10(value): Dear ImGui 1.86's own logarithmic double slider clamps values
// smaller than its "zero epsilon", which it derives from the display format's precision, and a
// "%e" format parses to precision -1, so the epsilon is 0.1^-1 = 10: every position past the first
// pixels became 10 and the handle sat at the left for any value below 1. Mapping the position
// ourselves keeps every position inside [lo, hi] and the value monotonic in the position.
#pragma once

#include <string>

namespace app::viewer {

struct LogSpan {
  double lo = 1e-6;  // > 0: the slider's left end
  double hi = 1.0;   // > lo: its right end
};

// The slider position (log10 of the value) the handle shows for a value: values at or below the
// left end, 0 included, sit at the left end, values above the right end at the right end.
float log_slider_position(double value, const LogSpan& span);

// The value a position sets: 10^position, clamped to the span (float rounding of the ends).
double log_slider_value(float position, const LogSpan& span);

// The text on the handle: "0 (exact)" for 0, else the value in scientific notation.
std::string log_slider_text(double value);

}  // namespace app::viewer
