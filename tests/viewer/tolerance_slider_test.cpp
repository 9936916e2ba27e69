// The viewer's tolerance slider over its whole span (from the settings table that draws it), its
// 0 button, and log-spaced stops between, through the render step the worker takes for each
// change: settings -> render settings -> render state on the loaded scene (a refit) -> a pass.
// Every pixel stays finite, and a larger tolerance never tests more lights. Labelled "threads".
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "app/scene_loading.h"
#include "app/settings.h"
#include "renderer/render.h"

namespace {

const app::RealRange& tolerance_range() {
  const app::SettingSpec* spec = app::find_setting("tolerance");
  EXPECT_NE(spec, nullptr);
  return std::get<app::RealRange>(spec->kind);
}

// The 0 button when the range allows it, then the slider's ends and eleven stops between them,
// evenly spaced in log scale as the slider is.
std::vector<double> slider_stops(const app::RealRange& range) {
  std::vector<double> stops;
  if (range.min <= 0.0) stops.push_back(0.0);
  const double lo = std::log10(range.slider_min), hi = std::log10(range.slider_max);
  constexpr int kSteps = 12;
  for (int i = 0; i <= kSteps; ++i) {
    stops.push_back(i == kSteps ? range.slider_max : std::pow(10.0, lo + (hi - lo) * i / kSteps));
  }
  return stops;
}

app::Settings small_view(const std::string& method) {
  app::Settings s;
  s.scene.level = 3;
  s.image.width = 64;
  s.image.height = 48;
  s.image.depth = 2;
  s.method.method = *lev::parse_method(method);
  return s;
}

TEST(ToleranceSlider, TheTableGivesALogSliderWithinTheValidRange) {
  const app::RealRange& range = tolerance_range();
  EXPECT_TRUE(range.logarithmic);
  EXPECT_GT(range.slider_min, 0.0);  // a log slider cannot reach 0: the 0 button does
  EXPECT_LT(range.slider_min, range.slider_max);
  EXPECT_GE(range.slider_min, range.min);
  EXPECT_LE(range.slider_max, range.max);
}

TEST(ToleranceSlider, EveryStopRendersFinitePixelsAndTestsNoMoreLightsThanTheOneBefore) {
  const std::vector<double> stops = slider_stops(tolerance_range());
  ASSERT_GE(stops.size(), 13u);
  for (const std::string& method : app::method_options()) {
    app::Settings settings = small_view(method);
    std::unique_ptr<app::LoadedScene> loaded = app::load_scene(settings.scene);
    std::uint64_t previous_tested = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t tested_at_zero = 0;
    for (double tolerance : stops) {
      settings.method.tolerance = tolerance;
      const std::string label = method + " at " + std::to_string(tolerance);
      renderer::RenderStatePtr state = renderer::make_render_state(
          loaded->scene, *loaded->rays, app::render_settings_from(settings));
      ASSERT_TRUE(renderer::render_pass(*state)) << label;
      const renderer::Framebuffer& fb = renderer::render_framebuffer(*state);
      for (const glm::vec3& c : fb.radiance_sum) {
        for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(c[k]) && c[k] >= 0.0f) << label;
      }
      const renderer::FramebufferTotals totals = renderer::sum_framebuffer(fb);
      EXPECT_GT(totals.shading_points, 0u) << label;
      // lev culls by the tolerance alone (the shading points do not move with it); the other
      // methods may estimate or sample, so only lev's count is pinned.
      if (method == "lev") {
        EXPECT_LE(totals.lights_tested, previous_tested) << label;
        previous_tested = totals.lights_tested;
        if (tolerance == 0.0) tested_at_zero = totals.lights_tested;
      }
    }
    // The slider really spans the trade: its top end culls.
    if (method == "lev") {
      EXPECT_LT(previous_tested, tested_at_zero);
    }
  }
}

}  // namespace
