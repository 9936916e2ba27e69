// `lev_bounded` in the renderer: at tolerance 0 its image equals rt's bit for bit; at a positive
// tolerance the image is the same for one and two threads and it tests more lights than lev.
#include <cstring>

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/building.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

renderer::Framebuffer render_bounded(const renderer::Scene& scene, const renderer::RayScene& rays,
                                     lev::Method method, float tolerance, int threads) {
  return render_test_image(scene, rays, method, tolerance, threads, 2);
}

TEST(LevBoundedRender, EqualsRtAtToleranceZeroAndIsDeterministic) {
  const renderer::Scene scene = scenes::build_building(3);
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_bounded(scene, rays, lev::Method::rt, 0.0f, 0);
  const renderer::Framebuffer exact =
      render_bounded(scene, rays, lev::Method::lev_bounded, 0.0f, 0);
  EXPECT_TRUE(bitwise_equal(rt, exact));
  EXPECT_EQ(rt.lights_tested, exact.lights_tested);
  const renderer::Framebuffer one = render_bounded(scene, rays, lev::Method::lev_bounded, 0.01f, 1);
  const renderer::Framebuffer two = render_bounded(scene, rays, lev::Method::lev_bounded, 0.01f, 2);
  EXPECT_TRUE(bitwise_equal(one, two));
  EXPECT_EQ(one.lights_tested, two.lights_tested);
  const renderer::Framebuffer plain = render_bounded(scene, rays, lev::Method::lev, 0.01f, 2);
  EXPECT_GT(one.lights_tested, plain.lights_tested);
  EXPECT_LT(one.lights_tested, rt.lights_tested);
}

}  // namespace
