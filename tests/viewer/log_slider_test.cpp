// The tolerance slider's own log mapping (app/viewer/log_slider.h) over the settings table's
// slider span: every position gives a value inside the span, values grow with the position, the
// handle of a value maps back to it, and 0 sits at the left end with its own text.
#include <algorithm>
#include <cmath>
#include <variant>

#include <gtest/gtest.h>

#include "app/settings.h"
#include "app/viewer/log_slider.h"

namespace {

using app::viewer::LogSpan;

LogSpan tolerance_span() {
  const app::SettingSpec* spec = app::find_setting("tolerance");
  EXPECT_NE(spec, nullptr);
  const auto& range = std::get<app::RealRange>(spec->kind);
  return LogSpan{std::max(range.min, range.slider_min), std::min(range.max, range.slider_max)};
}

TEST(LogSlider, EveryPositionGivesAValueInsideTheSpanGrowingWithThePosition) {
  const LogSpan span = tolerance_span();
  const float left = app::viewer::log_slider_position(span.lo, span);
  const float right = app::viewer::log_slider_position(span.hi, span);
  ASSERT_LT(left, right);
  double previous = 0.0;
  constexpr int kSteps = 400;
  for (int i = 0; i <= kSteps; ++i) {
    const float position = left + (right - left) * static_cast<float>(i) / kSteps;
    const double value = app::viewer::log_slider_value(position, span);
    EXPECT_GE(value, span.lo) << i;
    EXPECT_LE(value, span.hi) << i;
    EXPECT_GT(value, previous) << i;
    previous = value;
  }
  // Positions past the ends (a drag beyond the frame) stay at the ends.
  EXPECT_EQ(app::viewer::log_slider_value(left - 3.0f, span), span.lo);
  EXPECT_EQ(app::viewer::log_slider_value(right + 3.0f, span), span.hi);
}

TEST(LogSlider, TheHandleOfAValueMapsBackToItAndSmallerValuesSitFurtherLeft) {
  const LogSpan span = tolerance_span();
  float previous = app::viewer::log_slider_position(0.0, span);
  EXPECT_EQ(previous, app::viewer::log_slider_position(span.lo, span));  // 0 at the left end
  for (double value : {1e-5, 1e-4, 1e-3, 1e-2, 0.1, 0.5}) {
    const float position = app::viewer::log_slider_position(value, span);
    EXPECT_GT(position, previous) << value;
    EXPECT_NEAR(app::viewer::log_slider_value(position, span), value, value * 1e-5) << value;
    previous = position;
  }
  EXPECT_EQ(app::viewer::log_slider_position(10.0, span),
            app::viewer::log_slider_position(span.hi, span));
}

TEST(LogSlider, TheHandleTextNamesZeroAndShowsOtherValues) {
  EXPECT_EQ(app::viewer::log_slider_text(0.0), "0 (exact)");
  EXPECT_EQ(app::viewer::log_slider_text(0.01), "1.00e-02");
  EXPECT_EQ(app::viewer::log_slider_text(1.0), "1.00e+00");
}

}  // namespace
