#include "renderer/render.h"

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/ray_scene.h"
#include "scenes/building.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

struct TestScene {
  renderer::Scene scene;
  std::unique_ptr<renderer::RayScene> rays;
  explicit TestScene(int level) : scene(scenes::build_building(level)) {
    rays = std::make_unique<renderer::RayScene>(scene);
  }
};

renderer::Framebuffer render_test_scene(TestScene& t, lev::Method method, float tolerance,
                                        int threads, int passes, int width = 64, int height = 48) {
  return render_test_image(t.scene, *t.rays, method, tolerance, threads, passes, width, height);
}

TEST(Render, LevAtToleranceZeroEqualsRtBitForBit) {
  for (int level : {2, 3}) {
    TestScene t(level);
    const renderer::Framebuffer rt = render_test_scene(t, lev::Method::rt, 0.0f, 0, 1, 80, 60);
    const renderer::Framebuffer lev = render_test_scene(t, lev::Method::lev, 0.0f, 0, 1, 80, 60);
    EXPECT_TRUE(bitwise_equal(rt, lev)) << "level " << level;
    EXPECT_EQ(renderer::framebuffer_rgb8(rt), renderer::framebuffer_rgb8(lev));
    EXPECT_EQ(rt.lights_tested, lev.lights_tested);
    EXPECT_EQ(rt.shadow_rays, lev.shadow_rays);
    // The image is not trivially black.
    const renderer::FramebufferTotals totals = renderer::sum_framebuffer(rt);
    EXPECT_GT(totals.shading_points, 0u);
    EXPECT_GT(totals.shadow_rays, 0u);
  }
}

TEST(Render, LevAtPositiveToleranceTestsFewerLights) {
  TestScene t(3);
  const auto rt = renderer::sum_framebuffer(render_test_scene(t, lev::Method::rt, 0.0f, 0, 1));
  const auto lev = renderer::sum_framebuffer(render_test_scene(t, lev::Method::lev, 0.01f, 0, 1));
  EXPECT_EQ(rt.shading_points, lev.shading_points);
  EXPECT_LT(lev.lights_tested * 2, rt.lights_tested);
  EXPECT_GT(lev.nodes_visited, 0u);
}

TEST(Render, SameImageWhateverTheThreadCount) {
  TestScene t(3);
  for (lev::Method method : {lev::Method::rt, lev::Method::lev, lev::Method::ast}) {
    const renderer::Framebuffer one = render_test_scene(t, method, 0.01f, 1, 3);
    const renderer::Framebuffer two = render_test_scene(t, method, 0.01f, 2, 3);
    EXPECT_TRUE(bitwise_equal(one, two)) << lev::method_info(method).name;
    EXPECT_EQ(one.lights_tested, two.lights_tested);
    EXPECT_EQ(one.nodes_visited, two.nodes_visited);
  }
}

// The scene is read-only to a render: states with different methods and tolerances render it
// at the same time (the viewer's main render and its rt reference do), each getting the image it
// gets alone. Were a state to refit the shared hierarchy, the others would render with its
// volumes (and ThreadSanitizer, which runs this test, would see the writes).
TEST(Render, StatesWithDifferentTolerancesAndMethodsRenderOneSceneConcurrently) {
  const TestScene t(3);
  struct Job {
    lev::Method method;
    float tolerance;
  };
  const std::vector<Job> jobs = {{lev::Method::lev, 0.002f},
                                 {lev::Method::lev, 0.2f},
                                 {lev::Method::ast, 0.05f},
                                 {lev::Method::rt, 0.0f}};
  auto settings_for = [](const Job& job) {
    renderer::RenderSettings rs;
    rs.width = 48;
    rs.height = 36;
    rs.tile_size = 8;
    rs.threads = 2;
    rs.method = job.method;
    rs.tolerance = job.tolerance;
    return rs;
  };
  std::vector<renderer::Framebuffer> alone;
  for (const Job& job : jobs) {
    auto state = renderer::make_render_state(t.scene, *t.rays, settings_for(job));
    ASSERT_TRUE(renderer::render_pass(*state));
    alone.push_back(renderer::render_framebuffer(*state));
  }
  std::vector<renderer::RenderStatePtr> states;
  for (const Job& job : jobs)
    states.push_back(renderer::make_render_state(t.scene, *t.rays, settings_for(job)));
  std::vector<std::thread> threads;
  std::vector<int> complete(jobs.size(), 0);
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    threads.emplace_back([&, i] { complete[i] = renderer::render_pass(*states[i]) ? 1 : 0; });
  }
  for (std::thread& thread : threads) thread.join();
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_EQ(complete[i], 1);
    EXPECT_TRUE(bitwise_equal(renderer::render_framebuffer(*states[i]), alone[i]))
        << lev::method_info(jobs[i].method).name << " at " << jobs[i].tolerance;
  }
  // The two lev states really differ: each walked its own volumes.
  EXPECT_GT(renderer::sum_framebuffer(alone[0]).nodes_visited,
            renderer::sum_framebuffer(alone[1]).nodes_visited);
}

TEST(Render, CancelledPassResumesWithoutRepeatingTiles) {
  TestScene t(2);
  renderer::RenderSettings rs;
  rs.width = 64;
  rs.height = 48;
  rs.tile_size = 8;
  auto state = renderer::make_render_state(t.scene, *t.rays, rs);
  std::atomic<bool> cancel{true};
  EXPECT_FALSE(renderer::render_pass(*state, &cancel));
  EXPECT_EQ(renderer::render_passes_done(*state), 0);
  cancel = false;
  EXPECT_TRUE(renderer::render_pass(*state, &cancel));
  EXPECT_TRUE(renderer::render_pass(*state, &cancel));
  for (std::uint32_t s : renderer::render_framebuffer(*state).samples) ASSERT_EQ(s, 2u);
  const renderer::Framebuffer uninterrupted = render_test_scene(t, lev::Method::lev, 0.01f, 0, 2);
  EXPECT_TRUE(bitwise_equal(renderer::render_framebuffer(*state), uninterrupted));
  for (int tile = 0; tile < renderer::render_tile_count(*state); ++tile) {
    EXPECT_EQ(renderer::render_tile_status(*state, tile), renderer::TileStatus::done);
  }
}

// Every method: AST, which carries statistics from pass to pass, previews with a selector of its
// own; the others with the render's (its extent volumes fitted once), which previews never change.
TEST(Render, PreviewPassesSamplePixelCentresEveryStepAndLeaveTheRenderAlone) {
  TestScene t(2);
  for (const lev::MethodInfo& method : lev::method_table()) {
    SCOPED_TRACE(method.name);
    EXPECT_EQ(
        method.id == lev::Method::ast,
        lev::make_selector(t.scene.lights, lev::MethodParams{method.id})->learns_between_passes());
    renderer::RenderSettings rs;
    rs.width = 37;  // not a multiple of any step or of the tile size
    rs.height = 29;
    rs.tile_size = 8;
    rs.method = method.id;
    auto state = renderer::make_render_state(t.scene, *t.rays, rs);
    const auto plain = renderer::make_render_state(t.scene, *t.rays, rs);
    EXPECT_TRUE(renderer::render_pass(*plain));
    // A cancelled preview adds nothing; a step below 1 is refused.
    std::atomic<bool> cancel{true};
    EXPECT_FALSE(renderer::render_pass(*state, &cancel, nullptr, 4));
    for (std::uint32_t s : renderer::render_preview(*state).samples) EXPECT_EQ(s, 0u);
    EXPECT_THROW(renderer::render_pass(*state, nullptr, nullptr, 0), std::invalid_argument);
    for (int step : {8, 4, 2}) {
      ASSERT_TRUE(renderer::render_pass(*state, nullptr, nullptr, step));
      const renderer::Framebuffer& preview = renderer::render_preview(*state);
      ASSERT_EQ(preview.width, (rs.width + step - 1) / step);
      ASSERT_EQ(preview.height, (rs.height + step - 1) / step);
      const renderer::Framebuffer& pass0 = renderer::render_framebuffer(*plain);
      for (int py = 0; py < preview.height; ++py) {
        for (int px = 0; px < preview.width; ++px) {
          const std::size_t p = static_cast<std::size_t>(py * preview.width + px);
          const std::size_t i = static_cast<std::size_t>(py * step * rs.width + px * step);
          // The preview sample is pass 0's sample of the block's corner pixel.
          ASSERT_EQ(preview.samples[p], 1u);
          ASSERT_EQ(preview.radiance_sum[p], pass0.radiance_sum[i])
              << step << " " << px << "," << py;
          ASSERT_EQ(preview.lights_tested[p], pass0.lights_tested[i]);
        }
      }
    }
    // Nothing of the previews is in the render: no sample, no pass, no time, and the passes that
    // follow equal those of a state that never previewed.
    EXPECT_EQ(renderer::render_passes_done(*state), 0);
    EXPECT_EQ(renderer::render_seconds(*state), 0.0);
    for (std::uint32_t s : renderer::render_framebuffer(*state).samples) ASSERT_EQ(s, 0u);
    EXPECT_TRUE(renderer::render_pass(*state));
    EXPECT_TRUE(renderer::render_pass(*state));
    EXPECT_TRUE(renderer::render_pass(*plain));
    EXPECT_TRUE(
        bitwise_equal(renderer::render_framebuffer(*state), renderer::render_framebuffer(*plain)));
    EXPECT_EQ(renderer::render_framebuffer(*state).lights_tested,
              renderer::render_framebuffer(*plain).lights_tested);
  }
}

// Without jitter every pass samples the pixel centres: a deterministic method's passes all equal
// its first, while a sampling method still draws other lights each pass (its random stream is
// the pass's), so its passes converge to the one-pass rt image.
TEST(Render, WithoutJitterEveryPassSamplesThePixelCentres) {
  TestScene t(3);
  const auto passes_of = [&](lev::Method method, bool jitter, int passes) {
    renderer::RenderSettings rs;
    rs.width = 64;
    rs.height = 48;
    rs.tile_size = 8;
    rs.method = method;
    rs.jitter_pixels = jitter;
    auto state = renderer::make_render_state(t.scene, *t.rays, rs);
    for (int i = 0; i < passes; ++i) EXPECT_TRUE(renderer::render_pass(*state));
    return renderer::render_framebuffer(*state);
  };
  const renderer::Framebuffer one = passes_of(lev::Method::lev, false, 1);
  const renderer::Framebuffer centres = passes_of(lev::Method::lev, false, 4);
  const renderer::Framebuffer jittered = passes_of(lev::Method::lev, true, 4);
  for (std::size_t i = 0; i < one.radiance_sum.size(); ++i) {
    ASSERT_EQ(centres.samples[i], 4u);
    // Four equal samples: the sum is four times the one (exact in binary floating point up to
    // the one rounding of 3x).
    EXPECT_NEAR(centres.radiance_sum[i].x, 4.0f * one.radiance_sum[i].x,
                1e-6f * (1.0f + one.radiance_sum[i].x))
        << i;
  }
  EXPECT_EQ(renderer::framebuffer_rgb8(centres), renderer::framebuffer_rgb8(one));
  EXPECT_NE(renderer::framebuffer_rgb8(jittered), renderer::framebuffer_rgb8(one))
      << "jittered passes sample elsewhere in the pixels (the building's edges change)";
  const renderer::Framebuffer sampled = passes_of(lev::Method::light_tree, false, 2);
  const renderer::Framebuffer sampled_once = passes_of(lev::Method::light_tree, false, 1);
  bool passes_differ = false;
  for (std::size_t i = 0; i < sampled.radiance_sum.size(); ++i)
    passes_differ |= sampled.radiance_sum[i] != 2.0f * sampled_once.radiance_sum[i];
  EXPECT_TRUE(passes_differ) << "a sampling method draws other lights in its second pass";
}

TEST(Render, HugeToleranceLeavesOnlyAmbient) {
  TestScene t(2);
  const renderer::Framebuffer fb = render_test_scene(t, lev::Method::lev, 1e30f, 0, 1);
  const auto totals = renderer::sum_framebuffer(fb);
  EXPECT_EQ(totals.lights_tested, 0u);
  EXPECT_EQ(totals.shadow_rays, 0u);
  for (const glm::vec3& c : fb.radiance_sum) {
    ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
    ASSERT_LT(glm::max(c.x, glm::max(c.y, c.z)), 0.2f);  // ambient only (with reflections of it)
  }
}

}  // namespace
