// The stats record (app/render_stats.h): a method's settings are written as numbers where the
// method reads them and as null where its images do not depend on them.
#include "app/render_stats.h"

#include <gtest/gtest.h>

#include "lev/methods.h"

namespace {

app::RenderStats stats_of(const char* method) {
  app::Settings settings;
  settings.method.tolerance = 0.03;
  settings.method.relative_error = 0.05;
  settings.method.lights_per_point = 4;
  app::RenderStats stats;
  stats.method = method;
  stats.tolerance = settings.method.tolerance;
  app::set_stats_from_settings(stats, settings);
  return stats;
}

TEST(RenderStats, EachMethodShowsTheSettingsItReadsAndNullForTheRest) {
  for (const lev::MethodInfo& method : lev::method_table()) {
    const nlohmann::ordered_json j = app::render_stats_json(stats_of(method.name));
    SCOPED_TRACE(method.name);
    EXPECT_EQ(j.at("tolerance").is_null(), !method.uses_tolerance);
    EXPECT_EQ(j.at("relative_error").is_null(), !method.uses_relative_error);
    EXPECT_EQ(j.at("lights_per_point").is_null(), !method.stochastic);
    if (method.uses_tolerance) {
      EXPECT_DOUBLE_EQ(j.at("tolerance").get<double>(), 0.03);
    }
    if (method.uses_relative_error) {
      EXPECT_FLOAT_EQ(j.at("relative_error").get<float>(), 0.05f);
    }
    if (method.stochastic) {
      EXPECT_EQ(j.at("lights_per_point").get<int>(), 4);
    }
    EXPECT_TRUE(j.contains("time_setup_s"));
    EXPECT_FALSE(j.contains("time_refit_s"));
  }
  // rt reads none of them.
  const nlohmann::ordered_json rt = app::render_stats_json(stats_of("rt"));
  EXPECT_TRUE(rt.at("tolerance").is_null());
  EXPECT_TRUE(rt.at("relative_error").is_null());
  EXPECT_TRUE(rt.at("lights_per_point").is_null());
}

}  // namespace
