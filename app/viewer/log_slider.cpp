#include "app/viewer/log_slider.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace app::viewer {

float log_slider_position(double value, const LogSpan& span) {
  assert(span.lo > 0.0 && span.lo < span.hi);
  return static_cast<float>(std::log10(std::clamp(value, span.lo, span.hi)));
}

double log_slider_value(float position, const LogSpan& span) {
  assert(span.lo > 0.0 && span.lo < span.hi);
  return std::clamp(std::pow(10.0, static_cast<double>(position)), span.lo, span.hi);
}

std::string log_slider_text(double value) {
  if (value == 0.0) return "0 (exact)";
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

}  // namespace app::viewer
