// The methods that read the relative error (`lightcuts`, `lev_cut`) in the renderer: at relative
// error 0 the image equals rt's bit for bit (the building, with point lights behind walls, and
// the hall's spots); at the default the image is the same for one and two threads, close to rt's
// on the hall, where every light adds a little, with far fewer shadow rays than rt; on the stage,
// whose spots aim apart, the same for one and two threads too.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/methods.h"
#include "renderer/pixel_error.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/building.h"
#include "scenes/hall.h"
#include "scenes/stage_rig.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

renderer::Framebuffer render_relative(const renderer::Scene& scene, const renderer::RayScene& rays,
                                      lev::Method method, float relative_error, int threads,
                                      int width = 48, int height = 36) {
  renderer::RenderSettings rs = test_render_settings(method, width, height);
  rs.relative_error = relative_error;
  rs.threads = threads;
  return render_test_image(scene, rays, rs);
}

std::vector<lev::Method> relative_error_methods() {
  std::vector<lev::Method> methods;
  for (const lev::MethodInfo& info : lev::method_table()) {
    if (info.uses_relative_error) methods.push_back(info.id);
  }
  return methods;
}

class RelativeErrorRender : public testing::TestWithParam<lev::Method> {};

TEST(RelativeErrorMethods, LightcutsAndLevCutReadIt) {
  EXPECT_EQ(relative_error_methods(),
            (std::vector<lev::Method>{lev::Method::lightcuts, lev::Method::lev_cut}));
}

TEST_P(RelativeErrorRender, EqualsRtAtRelativeErrorZero) {
  for (const bool hall : {false, true}) {
    const renderer::Scene scene = hall ? scenes::build_hall(4) : scenes::build_building(3);
    const renderer::RayScene rays(scene);
    const renderer::Framebuffer exact = render_relative(scene, rays, GetParam(), 0.0f, 2);
    const renderer::Framebuffer rt = render_relative(scene, rays, lev::Method::rt, 0.0f, 2);
    EXPECT_TRUE(bitwise_equal(rt, exact)) << (hall ? "hall" : "building");
    EXPECT_EQ(renderer::sum_framebuffer(rt).shadow_rays,
              renderer::sum_framebuffer(exact).shadow_rays);
  }
}

TEST_P(RelativeErrorRender, DeterministicAndCloseToRtWithFewerRaysOnTheHall) {
  const renderer::Scene scene = scenes::build_hall(5);
  const renderer::RayScene rays(scene);
  const auto default_error = static_cast<float>(lev::kDefaultRelativeError);
  const renderer::Framebuffer one = render_relative(scene, rays, GetParam(), default_error, 1);
  const renderer::Framebuffer two = render_relative(scene, rays, GetParam(), default_error, 2);
  EXPECT_TRUE(bitwise_equal(one, two));
  EXPECT_EQ(one.shadow_rays, two.shadow_rays);
  EXPECT_EQ(one.lights_tested, two.lights_tested);
  EXPECT_EQ(one.nodes_visited, two.nodes_visited);
  const renderer::Framebuffer rt = render_relative(scene, rays, lev::Method::rt, 0.0f, 2);
  const renderer::PixelErrorStats error = renderer::summarize_pixel_error(
      renderer::pixel_error_pct(renderer::framebuffer_rgb8(one), renderer::framebuffer_rgb8(rt)));
  EXPECT_LT(error.average_pct, 0.5);
  EXPECT_LT(error.max_pct, 5.0);
  EXPECT_LT(renderer::sum_framebuffer(one).shadow_rays * 2,
            renderer::sum_framebuffer(rt).shadow_rays);
}

TEST_P(RelativeErrorRender, DeterministicOnTheStageWhoseSpotsAimApart) {
  // Spots aimed apart: lev_cut shades its small clusters from their own lights, its ray to one
  // drawn by a hash of the point (lev/important_lights.cpp, keep_cluster), never by the thread.
  const renderer::Scene scene = scenes::build_stage_rig(4);
  const renderer::RayScene rays(scene);
  for (const float relative_error : {0.05f, 0.3f}) {
    const renderer::Framebuffer one = render_relative(scene, rays, GetParam(), relative_error, 1);
    const renderer::Framebuffer two = render_relative(scene, rays, GetParam(), relative_error, 2);
    EXPECT_TRUE(bitwise_equal(one, two)) << relative_error;
    EXPECT_EQ(one.shadow_rays, two.shadow_rays) << relative_error;
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, RelativeErrorRender, testing::ValuesIn(relative_error_methods()),
                         [](const testing::TestParamInfo<lev::Method>& param) {
                           return std::string(lev::method_info(param.param).name);
                         });

}  // namespace
