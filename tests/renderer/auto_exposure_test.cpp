#include "renderer/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "scenes/building.h"
#include "scenes/scene_file.h"
#include "scenes/scene_instantiation.h"

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

// A lit quad on a few pixels of a black frame (zoomed out: about 27 of the preview's 6,912, under
// the 1 % the 99th percentile looks past): exposed by its own light, not left at EV 0, where its
// radiance of 55 to 320 showed white.
constexpr char kSmallLitQuadScene[] = R"({
  "levrt_scene": 1,
  "camera": {"position": [0, -100, 0], "target": [0, 0, 0], "fov_degrees": 45},
  "ambient": [0, 0, 0],
  "materials": [{"name": "grey", "colour": [0.8, 0.8, 0.8], "kd": 0.8}],
  "root": {"type": "union", "children": [
    {"type": "quad", "material": "grey", "corner": [-3, 0, -3], "edge_u": [6, 0, 0],
     "edge_v": [0, 0, 6]},
    {"type": "affine", "translate": [0, -2, 0],
     "child": {"type": "point_light", "intensity": [2000, 2000, 2000]}}]}})";

TEST(AutoExposure, ASmallLitObjectInABlackFrameIsExposedByItsOwnPixels) {
  const renderer::Scene scene =
      scenes::instantiate_scene(scenes::parse_scene_json(kSmallLitQuadScene, "small.json"));
  const renderer::RayScene rays(scene);
  renderer::RenderSettings settings;
  settings.width = 320;
  settings.height = 240;
  const double ev =
      renderer::auto_exposure_ev(scene, rays, settings, renderer::DisplayCurve::linear);
  // The quad's radiance is 0.64 x 2000 / 4 = 320 at its centre, about 55 at its edges: its lit
  // pixels' median (measured 57) is shown at 0.75 at EV -6.3.
  EXPECT_LT(ev, -5.0);
  EXPECT_GT(ev, -9.0);
}

}  // namespace
