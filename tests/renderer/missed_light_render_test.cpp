// The missed-light estimate in the renderer (renderer/missed_light.h): over many seeds its pixel
// sums match rt's radiance minus lev's (reflections included); on the building, whose walls hide
// every light lev culls, it reads about 0; it is the same for one and two threads and leaves the
// method's image untouched.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/missed_light.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/building.h"
#include "scenes/maze.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

renderer::Framebuffer render_missed(const renderer::Scene& scene, const renderer::RayScene& rays,
                                    lev::Method method, float tolerance, int missed_draws,
                                    std::uint64_t seed, int threads, int width, int height) {
  renderer::RenderSettings rs = test_render_settings(method, width, height);
  rs.tolerance = tolerance;
  rs.threads = threads;
  rs.seed = seed;
  rs.missed_draws = missed_draws;
  return render_test_image(scene, rays, rs);
}

glm::dvec3 sum(const std::vector<glm::vec3>& values) {
  glm::dvec3 s(0.0);
  for (const glm::vec3& v : values) s += glm::dvec3(v);
  return s;
}

TEST(MissedLightRender, ItsMeanOverSeedsIsRtMinusLev) {
  const renderer::Scene scene = scenes::build_maze(1);
  const renderer::RayScene rays(scene);
  constexpr int kWidth = 24, kHeight = 18;
  constexpr float kTolerance = 0.05f;
  const glm::dvec3 lost =
      sum(render_missed(scene, rays, lev::Method::rt, 0.0f, 0, 0, 0, kWidth, kHeight)
              .radiance_sum) -
      sum(render_missed(scene, rays, lev::Method::lev, kTolerance, 0, 0, 0, kWidth, kHeight)
              .radiance_sum);
  ASSERT_GT(lost.x, 0.01) << "lev must lose light here for the check to mean something";
  constexpr int kSeeds = 24;
  glm::dvec3 mean(0.0), variance(0.0);
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const renderer::Framebuffer fb =
        render_missed(scene, rays, lev::Method::lev, kTolerance, 4,
                      static_cast<std::uint64_t>(seed), 0, kWidth, kHeight);
    mean += sum(fb.missed_sum);
    variance += sum(fb.missed_variance_sum);
  }
  mean /= kSeeds;
  variance /= static_cast<double>(kSeeds) * kSeeds;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(mean[c], lost[c], 5.0 * std::sqrt(variance[c]) + 1e-4 * std::abs(lost[c])) << c;
  }
}

TEST(MissedLightRender, ReadsAboutZeroWhereWallsHideTheCulledLights) {
  const renderer::Scene scene = scenes::build_building(4);
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer fb =
      render_missed(scene, rays, lev::Method::lev, 0.01f, 16, 0, 0, 48, 36);
  const renderer::MissedLightStats s = renderer::missed_light_stats(fb);
  EXPECT_LT(s.average_pct, 0.05);
  // The certified bound, which assumes no shadows, says far more there.
  EXPECT_FALSE(fb.missed_sum.empty());
}

TEST(MissedLightRender, SameForAnyThreadCountAndTheImageIsUntouched) {
  const renderer::Scene scene = scenes::build_maze(1);
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer one =
      render_missed(scene, rays, lev::Method::lev_est, 0.05f, 8, 3, 1, 32, 24);
  const renderer::Framebuffer two =
      render_missed(scene, rays, lev::Method::lev_est, 0.05f, 8, 3, 2, 32, 24);
  const renderer::Framebuffer off =
      render_missed(scene, rays, lev::Method::lev_est, 0.05f, 0, 3, 2, 32, 24);
  EXPECT_EQ(one.missed_sum, two.missed_sum);
  EXPECT_EQ(one.missed_variance_sum, two.missed_variance_sum);
  EXPECT_TRUE(bitwise_equal(one, off));
  EXPECT_EQ(one.shadow_rays, off.shadow_rays);
  EXPECT_TRUE(off.missed_sum.empty());
}

}  // namespace
