// The settings table at the ends of the tolerance's range: the CLI and the viewer's typed value
// take any finite tolerance >= 0 as a double, and the renderer gets it as the hierarchy's float.
// Below the smallest float that is 0 (no culling: the image equals rt, Extremes tests), above the
// largest float +inf (every light culled).
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/settings.h"

namespace {

float renderer_tolerance_for(const std::string& text) {
  app::Settings settings;
  app::set_setting(settings, *app::find_setting("tolerance"), text);
  return app::render_settings_from(settings).tolerance;
}

TEST(Settings, ToleranceExtremesReachTheRendererAsTheFloatLimits) {
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(renderer_tolerance_for("0"), 0.0f);
  EXPECT_EQ(renderer_tolerance_for("4.9406564584124654e-324"),
            0.0f);  // the smallest positive double
  EXPECT_EQ(renderer_tolerance_for("1e-300"), 0.0f);
  EXPECT_EQ(renderer_tolerance_for("1e-400"), 0.0f);  // underflows to 0 as it is read
  EXPECT_EQ(renderer_tolerance_for("1e-45"), std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(renderer_tolerance_for("0.01"), 0.01f);
  EXPECT_EQ(renderer_tolerance_for("1e300"), inf);
  EXPECT_EQ(renderer_tolerance_for("1.7976931348623157e308"), inf);  // the largest double
}

TEST(Settings, TheSmallestPositiveDoubleIsKeptAsItself) {
  app::Settings settings;
  app::set_setting(settings, *app::find_setting("tolerance"), "4.9406564584124654e-324");
  EXPECT_EQ(settings.method.tolerance, std::numeric_limits<double>::denorm_min());
}

TEST(Settings, NonFiniteAndNegativeTolerancesAreRefused) {
  app::Settings settings;
  for (const std::string text : {"1e999", "inf", "nan", "-4.9406564584124654e-324", "-1"}) {
    EXPECT_THROW(app::set_setting(settings, *app::find_setting("tolerance"), text), app::UsageError)
        << text;
  }
}

}  // namespace
