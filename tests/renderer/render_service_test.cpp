// The render service: a job's result is the render step's own framebuffer with its totals and
// rendered pixels, render_passes equals a job run by hand, and a cancelled render returns no
// result.
#include "renderer/render_service.h"

#include <atomic>
#include <cstring>

#include <gtest/gtest.h>

#include "renderer/process_cpu_time.h"
#include "renderer/ray_scene.h"
#include "scenes/building.h"

namespace {

renderer::RenderSettings small_settings(lev::Method method, int stride) {
  renderer::RenderSettings rs;
  rs.width = 40;
  rs.height = 30;
  rs.tile_size = 8;
  rs.method = method;
  rs.pixel_stride = stride;
  return rs;
}

TEST(RenderService, TheResultIsTheRenderStepsFramebufferWithItsTotalsAndPixels) {
  const renderer::Scene scene = scenes::build_building(2);
  const renderer::RayScene rays(scene);
  for (int stride : {1, 3}) {
    const renderer::RenderSettings rs = small_settings(lev::Method::ast, stride);
    renderer::RenderStatePtr state = renderer::make_render_state(scene, rays, rs);
    ASSERT_TRUE(renderer::render_pass(*state));
    ASSERT_TRUE(renderer::render_pass(*state));
    const renderer::Framebuffer& expected = renderer::render_framebuffer(*state);

    renderer::RenderResult result;
    ASSERT_TRUE(renderer::render_passes(scene, rays, rs, 2, result));
    EXPECT_EQ(result.passes, 2);
    EXPECT_EQ(result.framebuffer.samples, expected.samples);
    ASSERT_EQ(result.framebuffer.radiance_sum.size(), expected.radiance_sum.size());
    EXPECT_EQ(std::memcmp(result.framebuffer.radiance_sum.data(), expected.radiance_sum.data(),
                          expected.radiance_sum.size() * sizeof(glm::vec3)),
              0);
    const renderer::FramebufferTotals totals = renderer::sum_framebuffer(expected);
    EXPECT_EQ(result.totals.shading_points, totals.shading_points);
    EXPECT_EQ(result.totals.lights_tested, totals.lights_tested);
    const std::uint64_t pixels =
        static_cast<std::uint64_t>((40 + stride - 1) / stride) * ((30 + stride - 1) / stride);
    EXPECT_EQ(result.rendered_pixels, pixels) << "stride " << stride;
    EXPECT_EQ(result.rendered_rgb.size(), 3 * pixels);
    EXPECT_EQ(result.rendered_rgb, renderer::rendered_rgb8(expected));
    EXPECT_GT(result.render_seconds, 0.0);
    EXPECT_GT(result.method_bytes, 0u);  // ast's statistics
  }
}

TEST(RenderService, TheSetupsCpuTimeIsPartOfTheRendersAndDoesNotGrowWithThePixels) {
  const renderer::Scene scene = scenes::build_building(2);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs = small_settings(lev::Method::lev, 1);
  rs.rt_fallback = true;  // its probe is part of the set-up
  const double cpu_start = renderer::process_cpu_seconds();
  renderer::RenderResult result;
  ASSERT_TRUE(renderer::render_passes(scene, rays, rs, 1, result));
  const double cpu_spent = renderer::process_cpu_seconds() - cpu_start;
  EXPECT_GT(result.setup_cpu_seconds, 0.0);  // extent volumes fitted, the probe shaded
  EXPECT_LE(result.setup_cpu_seconds, cpu_spent);
  ASSERT_TRUE(result.rt_fallback.has_value());
  // The same set-up work for one pixel in 16: the probe's grid and the volumes do not depend on
  // the pixels rendered (its time may differ; its counts may not).
  rs.pixel_stride = 4;
  renderer::RenderResult subsampled;
  ASSERT_TRUE(renderer::render_passes(scene, rays, rs, 1, subsampled));
  ASSERT_TRUE(subsampled.rt_fallback.has_value());
  EXPECT_EQ(subsampled.rt_fallback->points, result.rt_fallback->points);
  EXPECT_EQ(subsampled.rt_fallback->method_cost_rays, result.rt_fallback->method_cost_rays);
}

TEST(RenderService, ACancelledRenderHasNoResult) {
  const renderer::Scene scene = scenes::build_building(2);
  const renderer::RayScene rays(scene);
  const std::atomic<bool> cancel{true};
  renderer::RenderResult result;
  int passes_reported = 0;
  EXPECT_FALSE(renderer::render_passes(scene, rays, small_settings(lev::Method::lev, 1), 3, result,
                                       &cancel, [&](int, double) { ++passes_reported; }));
  EXPECT_EQ(passes_reported, 0);
  EXPECT_EQ(result.passes, 0);
  EXPECT_TRUE(result.framebuffer.samples.empty());
}

}  // namespace
