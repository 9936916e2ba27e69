#include "renderer/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "scenes/building.h"

namespace {

TEST(AutoExposure, PercentileOfTheSampledPixels) {
  renderer::Framebuffer f = renderer::make_framebuffer(10, 10);
  for (std::size_t i = 0; i < f.radiance_sum.size(); ++i) {
    f.samples[i] = 2;
    f.radiance_sum[i] = glm::vec3(2.0f * static_cast<float>(i));  // luminance i
  }
  f.samples[99] = 0;  // no sample: not counted
  EXPECT_NEAR(renderer::luminance_percentile(f, 0.0), 0.0, 1e-6);
  EXPECT_NEAR(renderer::luminance_percentile(f, 1.0), 98.0, 1e-4);
  EXPECT_NEAR(renderer::luminance_percentile(f, 0.5), 49.0, 1e-4);
}

TEST(AutoExposure, PutsThePercentileAtTheDisplayedTarget) {
  for (renderer::DisplayCurve c : {renderer::DisplayCurve::linear, renderer::DisplayCurve::srgb,
                                   renderer::DisplayCurve::neutral}) {
    for (double y : {1e-6, 0.03, 1.0, 500.0}) {
      const double ev = renderer::exposure_for_percentile(y, c);
      const glm::vec3 shown = renderer::display_colour(glm::vec3(static_cast<float>(y)),
                                                       renderer::exposure_scale(ev), c);
      EXPECT_NEAR(shown.x, renderer::kAutoExposureDisplayedTarget, 1e-3) << y;
    }
  }
  EXPECT_EQ(renderer::exposure_for_percentile(0.0, renderer::DisplayCurve::srgb), 0.0);
}

// Deterministic, and within the range it may pick, on a built-in scene.
TEST(AutoExposure, IsDeterministic) {
  const renderer::Scene scene = scenes::build_building(3);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  const double ev = renderer::auto_exposure_ev(scene, rays, settings, renderer::DisplayCurve::srgb);
  EXPECT_EQ(ev, renderer::auto_exposure_ev(scene, rays, settings, renderer::DisplayCurve::srgb));
  EXPECT_GT(ev, renderer::kAutoExposureMinEv);
  EXPECT_LT(ev, renderer::kAutoExposureMaxEv);
}

}  // namespace
