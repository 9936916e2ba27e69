// The rt fallback (renderer/rt_fallback.h): a deterministic method whose probe says its work comes
// to rt's shades with rt's loop, bit for bit rt's image; one whose walk saves work keeps its own
// image bit for bit; the choice is the same whatever the threads, tiles and subsample; it is made
// only when asked, for the methods it applies to, and probing never teaches a learning method.
#include <gtest/gtest.h>

#include "lev/methods.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "renderer/rt_fallback.h"
#include "scenes/building.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

struct FallbackRender {
  renderer::Framebuffer image;
  std::optional<renderer::RtFallbackProbe> probe;
};

FallbackRender render_with_fallback(const renderer::Scene& scene, const renderer::RayScene& rays,
                                    renderer::RenderSettings settings, int passes = 2) {
  auto state = renderer::make_render_state(scene, rays, settings);
  for (int i = 0; i < passes; ++i) EXPECT_TRUE(renderer::render_pass(*state));
  FallbackRender out{renderer::render_framebuffer(*state), std::nullopt};
  if (const renderer::RtFallbackProbe* probe = renderer::render_rt_fallback(*state))
    out.probe = *probe;
  return out;
}

renderer::RenderSettings fallback_settings(lev::Method method, float tolerance, bool fallback) {
  renderer::RenderSettings rs = test_render_settings(method, 48, 36);
  rs.tolerance = tolerance;
  rs.rt_fallback = fallback;
  return rs;
}

bool no_node_visited(const renderer::Framebuffer& image) {
  for (const auto visited : image.nodes_visited) {
    if (visited != 0) return false;
  }
  return true;
}

TEST(RtFallback, AWalkThatAdmitsEveryLightShadesWithRtsLoop) {
  const renderer::Scene scene = scenes::build_building(3);
  const renderer::RayScene rays(scene);
  const FallbackRender rt =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::rt, 0.0f, true));
  // At tolerance 0 lev casts every ray rt casts and walks its hierarchy besides.
  const FallbackRender own =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::lev, 0.0f, false));
  const FallbackRender chosen =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::lev, 0.0f, true));
  EXPECT_FALSE(rt.probe);   // rt is the fallback: nothing to choose
  EXPECT_FALSE(own.probe);  // not asked
  ASSERT_TRUE(chosen.probe);
  EXPECT_TRUE(chosen.probe->use_rt);
  EXPECT_FALSE(chosen.probe->rt_cost_is_lower_bound);  // rt's rays were counted
  EXPECT_GT(chosen.probe->method_cost_rays, chosen.probe->rt_cost_rays);
  EXPECT_GT(chosen.probe->points, 0);
  EXPECT_TRUE(bitwise_equal(chosen.image, rt.image));
  EXPECT_EQ(chosen.image.lights_tested, rt.image.lights_tested);
  EXPECT_FALSE(no_node_visited(own.image));
  EXPECT_TRUE(no_node_visited(chosen.image));
}

TEST(RtFallback, AWalkThatCullsMostLightsKeepsItsOwnImage) {
  const renderer::Scene scene = scenes::build_building(5);
  const renderer::RayScene rays(scene);
  const FallbackRender own =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::lev, 0.01f, false));
  const FallbackRender chosen =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::lev, 0.01f, true));
  ASSERT_TRUE(chosen.probe);
  EXPECT_FALSE(chosen.probe->use_rt);
  EXPECT_LT(chosen.probe->method_cost_rays, 0.5 * chosen.probe->rt_cost_rays);
  EXPECT_TRUE(bitwise_equal(chosen.image, own.image));
  EXPECT_EQ(chosen.image.nodes_visited, own.image.nodes_visited);
}

TEST(RtFallback, EveryDeterministicMethodRendersEitherItsOwnImageOrRts) {
  const renderer::Scene scene = scenes::build_building(3);
  const renderer::RayScene rays(scene);
  const FallbackRender rt =
      render_with_fallback(scene, rays, fallback_settings(lev::Method::rt, 0.0f, false));
  for (const lev::MethodInfo& method : lev::method_table()) {
    SCOPED_TRACE(method.name);
    renderer::RenderSettings settings = fallback_settings(method.id, 0.01f, true);
    const FallbackRender chosen = render_with_fallback(scene, rays, settings);
    EXPECT_EQ(chosen.probe.has_value(), lev::rt_fallback_applies(method));
    settings.rt_fallback = false;
    // Two passes: a method that learns between passes (ast) must not have learnt from the probe.
    const FallbackRender own = render_with_fallback(scene, rays, settings);
    const bool use_rt = chosen.probe && chosen.probe->use_rt;
    EXPECT_TRUE(bitwise_equal(chosen.image, use_rt ? rt.image : own.image));
  }
}

TEST(RtFallback, TheChoiceIsTheSameForAnyThreadsTilesAndSubsample) {
  const renderer::Scene scene = scenes::build_building(4);
  const renderer::RayScene rays(scene);
  for (const lev::Method method : {lev::Method::lev, lev::Method::lev_bounded}) {
    renderer::RenderSettings settings = fallback_settings(method, 0.003f, true);
    settings.threads = 1;
    const FallbackRender one = render_with_fallback(scene, rays, settings, 1);
    settings.threads = 2;
    settings.tile_size = 5;
    settings.pixel_stride = 3;
    const FallbackRender other = render_with_fallback(scene, rays, settings, 1);
    ASSERT_TRUE(one.probe && other.probe);
    EXPECT_EQ(one.probe->use_rt, other.probe->use_rt);
    EXPECT_EQ(one.probe->points, other.probe->points);
    EXPECT_EQ(one.probe->method_cost_rays, other.probe->method_cost_rays);
    EXPECT_EQ(one.probe->rt_cost_rays, other.probe->rt_cost_rays);
  }
}

// Among many lights a walk that culls well costs less than rt's scan of every light alone: rt's
// rays are then not counted (the probe stays cheap at a million lights), and the choice is the
// method's. With rt's rays counted the same choice is made (the lower bound only skips work).
TEST(RtFallback, AWalkCheaperThanRtsScanAloneSkipsCountingRtsRays) {
  const renderer::Scene scene = scenes::build_building(7);
  const renderer::RayScene rays(scene);
  const renderer::RenderSettings settings = fallback_settings(lev::Method::lev, 0.01f, true);
  auto state = renderer::make_render_state(scene, rays, settings);
  const renderer::RtFallbackProbe* probe = renderer::render_rt_fallback(*state);
  ASSERT_TRUE(probe);
  EXPECT_TRUE(probe->rt_cost_is_lower_bound);
  EXPECT_FALSE(probe->use_rt);
  EXPECT_LT(probe->method_cost_rays, probe->rt_cost_rays);
  EXPECT_GT(probe->method_cost_rays, 0.0);
}

TEST(RtFallback, TheProbeGridShrinksAsTheLightsGrow) {
  EXPECT_EQ(renderer::probe_grid_side(1), renderer::kProbeGridSide);
  EXPECT_EQ(renderer::probe_grid_side(16384), renderer::kProbeGridSide);
  EXPECT_EQ(renderer::probe_grid_side(std::size_t{1} << 20), 4);
  EXPECT_EQ(renderer::probe_grid_side(std::size_t{1} << 30), renderer::kMinProbeGridSide);
}

}  // namespace
