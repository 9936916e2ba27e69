// The settings table at the ends of the tolerance's range: the CLI and the viewer's typed value
// take any finite tolerance >= 0 as a double, and the renderer gets it as the hierarchy's float.
// Below the smallest float that is 0 (no culling: the image equals rt, Extremes tests), above the
// largest float +inf (every light culled). Every numeric setting reads the one decimal grammar.
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "app/settings.h"
#include "lev/methods.h"

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

// The numbers' grammar (app/settings.h): decimal, no sign but '-', no space, no hex, no words.
TEST(Settings, TheNumberGrammarIsDecimalOnly) {
  for (const std::string good : {"0", "64", "-3", "007"})
    EXPECT_TRUE(app::is_decimal_integer(good));
  for (const std::string bad : {"", "-", "+64", " 64", "64 ", "\t64", "0x40", "6e1", "6.0", "1_0"})
    EXPECT_FALSE(app::is_decimal_integer(bad)) << "'" << bad << "'";
  for (const std::string good :
       {"0", "0.5", ".5", "5.", "-0.25", "1e-3", "2E+2", "4.9406564584124654e-324"}) {
    EXPECT_TRUE(app::is_decimal_real(good)) << good;
  }
  for (const std::string bad : {"", ".", "-", "+0.1", " 0.1", "0.1 ", "0x1p-3", "0x10", "inf",
                                "-inf", "nan", "infinity", "1e", "1e+", "e3", "1.2.3", "1,5"}) {
    EXPECT_FALSE(app::is_decimal_real(bad)) << "'" << bad << "'";
  }
}

// Every number of the settings table, which the CLI flags and the viewer's typed values and
// scripts all go through: a leading space or '+', a trailing space and hex were taken by some
// (--tolerance 0x1p-3 as 0.125, --width ' 64' and '+64' as 64). Each is refused naming the setting
// and the value as typed; the same number in plain decimal is taken.
TEST(Settings, EveryNumericSettingRefusesSignsSpacesAndHex) {
  for (const app::SettingSpec& spec : app::setting_table()) {
    std::string plain;
    if (const auto* r = std::get_if<app::IntRange>(&spec.kind)) {
      plain = std::to_string(r->max);
    } else if (const auto* d = std::get_if<app::RealRange>(&spec.kind)) {
      plain = d->min < 0.0 ? "-1" : "1";
    } else {
      continue;
    }
    app::Settings settings;
    EXPECT_NO_THROW(app::set_setting(settings, spec, plain)) << spec.name << " " << plain;
    const std::vector<std::string> bad_texts = {" " + plain, "+" + plain, plain + " ", "\t" + plain,
                                                "0x1",       "0x1p-3",    "0x1P+0"};
    for (const std::string& bad : bad_texts) {
      try {
        app::set_setting(settings, spec, bad);
        ADD_FAILURE() << spec.name << " took '" << bad << "'";
      } catch (const app::UsageError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(std::string("--") + spec.name + ": must be ", 0), 0u) << message;
        EXPECT_NE(message.find("got '" + bad + "'"), std::string::npos) << message;
      }
    }
  }
}

// The help of --relative-error (the CLI's --help, the viewer's tooltip) named lightcuts alone,
// while lev_cut reads it too: every method that reads a setting is named in its help.
TEST(Settings, TheRelativeErrorsHelpNamesEveryMethodThatReadsIt) {
  const std::string help = app::find_setting("relative-error")->help;
  for (const lev::MethodInfo& m : lev::method_table()) {
    if (m.uses_relative_error) {
      EXPECT_NE(help.find(m.name), std::string::npos) << m.name;
    }
  }
}

}  // namespace
