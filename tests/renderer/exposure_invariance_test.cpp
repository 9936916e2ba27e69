// The tolerance is in displayed units (RenderSettings::exposure_ev): a scene 100 times darker
// shown log2(100) EV brighter culls the same lights and shows the same image, for every method
// that reads a tolerance or an absolute floor; and only those methods' radiance depends on the
// exposure.
#include <cmath>
#include <variant>

#include <gtest/gtest.h>

#include "renderer/error_bound.h"
#include "renderer/pixel_error.h"
#include "renderer/ray_scene.h"
#include "renderer/render_service.h"
#include "scenes/building.h"
#include "scenes/hall.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/test_render.h"

namespace {

void scale_lights(scenes::SceneNode& node, float factor) {
  if (auto* point = std::get_if<scenes::PointLightSource>(&node.data)) point->intensity *= factor;
  if (auto* spot = std::get_if<scenes::SpotLightSource>(&node.data)) spot->intensity *= factor;
  for (scenes::SceneNode& child : node.children) scale_lights(child, factor);
}

// Every light, the ambient light, the background and the suns times factor.
scenes::SceneDescription scaled(scenes::SceneDescription scene, float factor) {
  scale_lights(scene.root, factor);
  for (scenes::Master& master : scene.masters) scale_lights(master.node, factor);
  for (renderer::DirectionalLight& sun : scene.directional_lights) sun.irradiance *= factor;
  scene.ambient *= factor;
  scene.background *= factor;
  return scene;
}

struct ExposedRender {
  renderer::RenderResult result;
  double lights_tested_avg = 0.0;
};

ExposedRender render_at_exposure(const scenes::SceneDescription& description, lev::Method method,
                                 double exposure_ev) {
  const renderer::Scene scene = scenes::instantiate_scene(description);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings settings = test_render_settings(method, 48, 36);
  settings.tolerance = 0.01f;
  settings.exposure_ev = exposure_ev;
  settings.compute_error_bound = true;
  ExposedRender r;
  EXPECT_TRUE(renderer::render_passes(scene, rays, settings, 1, r.result));
  r.lights_tested_avg = static_cast<double>(r.result.totals.lights_tested) /
                        static_cast<double>(r.result.totals.shading_points);
  return r;
}

class ExposureInvariance : public ::testing::TestWithParam<lev::Method> {};

TEST_P(ExposureInvariance, ADarkerSceneAtAHigherExposureCullsTheSame) {
  const double ev = std::log2(100.0);
  for (const scenes::SceneDescription& scene :
       {scenes::describe_building(3), scenes::describe_hall(3)}) {
    const ExposedRender bright = render_at_exposure(scene, GetParam(), 0.0);
    const ExposedRender dark = render_at_exposure(scaled(scene, 0.01f), GetParam(), ev);
    const std::string label = scene.name + " " + lev::method_info(GetParam()).name;
    ASSERT_GT(bright.lights_tested_avg, 0.0) << label;
    EXPECT_NEAR(dark.lights_tested_avg / bright.lights_tested_avg, 1.0, 0.01) << label;
    // The same displayed image and the same error bound on the displayed scale, within rounding.
    const auto error = renderer::summarize_pixel_error(
        renderer::pixel_error_pct(dark.result.rendered_rgb, bright.result.rendered_rgb));
    EXPECT_LT(error.max_pct, 0.5) << label;
    const auto bound_bright = renderer::error_bound_stats(bright.result.totals);
    const auto bound_dark = renderer::error_bound_stats(dark.result.totals);
    EXPECT_NEAR(bound_dark.average_pct, bound_bright.average_pct,
                0.01 * bound_bright.average_pct + 1e-6)
        << label;
    // Without the exposure the dark scene culls far more: the tolerance would mean 100x more.
    const ExposedRender unexposed = render_at_exposure(scaled(scene, 0.01f), GetParam(), 0.0);
    if (GetParam() != lev::Method::lev_cut) {
      EXPECT_LT(unexposed.lights_tested_avg, 0.9 * bright.lights_tested_avg) << label;
    }
  }
}

// The exposure changes a method's radiance exactly when its row says it reads the display scale
// (what makes the viewer render it again at a new exposure, app::restart_needed): rt's and the
// samplers' radiance is the same bit for bit at any exposure.
TEST(ExposureDependence, ARendersRadianceDependsOnTheExposureIffItReadsTheDisplayScale) {
  // The building, its lights falling off behind walls: a darker exposure culls more of them.
  const renderer::Scene scene = scenes::instantiate_scene(scenes::describe_building(3));
  const renderer::RayScene rays(scene);
  for (const lev::MethodInfo& method : lev::method_table()) {
    renderer::RenderSettings settings = test_render_settings(method.id, 48, 36);
    settings.tolerance = 0.05f;
    const renderer::Framebuffer at_zero = render_test_image(scene, rays, settings);
    settings.exposure_ev = -8.0;
    const renderer::Framebuffer brighter = render_test_image(scene, rays, settings);
    EXPECT_EQ(at_zero.radiance_sum != brighter.radiance_sum, method.reads_display_scale)
        << method.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, ExposureInvariance,
                         ::testing::Values(lev::Method::ast, lev::Method::lev,
                                           lev::Method::lev_bounded, lev::Method::lev_est,
                                           lev::Method::lev_mc, lev::Method::lev_cut),
                         [](const ::testing::TestParamInfo<lev::Method>& param) {
                           return std::string(lev::method_info(param.param).name);
                         });

}  // namespace
