// `lev_mc` and `light_tree` in the renderer, on small random scenes with occluders, instanced
// and scaled lights, spotlights and a mirror: the mean over passes converges to rt's image of
// the same passes (per pixel within a bound derived from the measured variance of the
// difference, over the image within the measured spread of the image's difference, and the error
// after 64 passes at most 0.45x the error after 8); the images do not
// depend on thread count or tile order; at tolerance 0 lev_mc equals rt bit for bit; and the
// framebuffer's squared sums give the noise estimate the measured spread of the passes gives.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lev/light_description.h"
#include "renderer/pixel_noise.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "renderer/shapes.h"
#include "scenes/building.h"
#include "tests/lev/random_light_scenes.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

using lev_test::Random;

renderer::Scene random_scene(std::uint64_t seed) {
  Random r(seed);
  renderer::Scene scene;
  scene.name = "random";
  scene.ambient = glm::vec3(0.0f);
  scene.materials.push_back({});
  renderer::Material mirror;
  mirror.kd = 0.3f;
  mirror.kr = 0.5f;
  mirror.ks = 0.3f;
  scene.materials.push_back(mirror);
  renderer::Prototype room;
  renderer::TriangleMesh floor;
  renderer::add_quad(floor, {-12, -12, 0}, {24, 0, 0}, {0, 24, 0});
  room.meshes.push_back(floor);
  renderer::TriangleMesh boxes;
  for (int i = 0; i < 6; ++i) {  // occluders between the lights and the floor
    const glm::vec3 lo(r.uniform(-8, 6), r.uniform(-8, 6), r.uniform(0.0f, 2.0f));
    renderer::add_box(boxes, lo,
                      lo + glm::vec3(r.uniform(0.5f, 3), r.uniform(0.5f, 3), r.uniform(0.2f, 2)));
  }
  room.meshes.push_back(boxes);
  room.spheres.push_back({{r.uniform(-4, 4), r.uniform(-4, 4), 1.0f}, 1.0f, 1});
  scene.geometry.prototypes.push_back(room);
  scene.geometry.instances.push_back({0, lev::Similarity{}});

  // A master of a few lights, instanced under rotations and scales, plus single lights.
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> master;
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 p(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(0.0f, 1.0f));
    const float intensity = r.uniform(0.2f, 2.0f);
    if (i % 2 == 0) {
      master.push_back(
          lev::extent_volume_node(lev::light_node(lev::make_point_light(p, glm::vec3(intensity)))));
    } else {
      master.push_back(lev::extent_volume_node(lev::light_node(lev::make_spot_light(
          p, glm::normalize(glm::vec3(r.uniform(-1, 1), r.uniform(-1, 1), -2.0f)),
          glm::vec3(intensity, 0.7f * intensity, 0.4f * intensity), r.uniform(0.3f, 1.2f), 1.0f))));
    }
  }
  tree.masters.push_back(lev::union_node(std::move(master)));
  std::vector<lev::LightDescriptionNode> roots;
  for (int i = 0; i < 5; ++i) {
    lev::Similarity xf = lev::make_rotation({0, 0, 1}, r.uniform(0.0f, 6.28f));
    xf = lev::compose(xf, lev::make_scale(r.uniform(0.5f, 1.5f)));
    xf = lev::compose(
        lev::make_translation({r.uniform(-8, 8), r.uniform(-8, 8), r.uniform(3.0f, 6.0f)}), xf);
    roots.push_back(lev::extent_volume_node(lev::affine_node(xf, lev::instance_node(0))));
  }
  for (int i = 0; i < 6; ++i) {
    roots.push_back(lev::light_node(
        lev::make_point_light({r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(2.5f, 6.0f)},
                              glm::vec3(r.uniform(0.05f, 1.0f)))));
  }
  tree.root = lev::union_node(std::move(roots));
  scene.light_description = tree;
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -16, 10};
  scene.camera.target = {0, 0, 0};
  return scene;
}

renderer::RenderSettings sampling_settings(lev::Method method, float tolerance, int threads = 2,
                                           int tile_size = 8, int lights_per_point = 1) {
  renderer::RenderSettings rs;
  rs.lights_per_point = lights_per_point;
  rs.width = 40;
  rs.height = 30;
  rs.method = method;
  rs.tolerance = tolerance;
  rs.threads = threads;
  rs.tile_size = tile_size;
  rs.max_depth = 2;
  return rs;
}

constexpr int kPasses = 256;
constexpr int kLightsPerPoint = 4;

double channel_sum(const glm::vec3& v) {
  return static_cast<double>(v.x) + v.y + v.z;
}

// Average over pixels of sum_c |mean_a - mean_b|.
double mean_error(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b, int passes) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 d = glm::abs(a[i] - b[i]) / static_cast<double>(passes);
    sum += d.x + d.y + d.z;
  }
  return sum / static_cast<double>(a.size());
}

// The sampled passes' mean against rt's of the same passes. k lights per point (lights_per_point)
// and enough passes that the rare draws of lights hidden behind occluders (the importance does
// not know visibility: a light with probability 1e-3 may carry a pixel's whole shadowed value)
// are seen often enough for the measured variance to stand for the true one.
void expect_converges_to_rt(lev::Method method, float tolerance, std::uint64_t seed) {
  const renderer::Scene scene = random_scene(seed);
  const renderer::RayScene rays(scene);
  auto rt = renderer::make_render_state(scene, rays, sampling_settings(lev::Method::rt, 0.0f));
  auto sampled = renderer::make_render_state(
      scene, rays, sampling_settings(method, tolerance, 2, 8, kLightsPerPoint));
  const std::size_t n = 40 * 30;
  // Per pixel: the passes' samples summed, and the difference sampled - rt per pass (its mean
  // and spread): both states draw the same jitter for a pass, so only the light sampling differs.
  std::vector<glm::dvec3> rt_sum(n, glm::dvec3(0.0)), sampled_sum(n, glm::dvec3(0.0));
  std::vector<double> diff_sum(n, 0.0), diff_square_sum(n, 0.0);
  std::vector<glm::vec3> rt_before(n, glm::vec3(0.0f)), sampled_before(n, glm::vec3(0.0f));
  double error_8 = 0.0, error_64 = 0.0;
  // Per pass, the difference summed over the image: a sum of many pixels' independent draws, so
  // close to normal even where single pixels are not.
  double image_sum = 0.0, image_square_sum = 0.0;
  for (int pass = 1; pass <= kPasses; ++pass) {
    ASSERT_TRUE(renderer::render_pass(*rt));
    ASSERT_TRUE(renderer::render_pass(*sampled));
    const renderer::Framebuffer& a = renderer::render_framebuffer(*rt);
    const renderer::Framebuffer& b = renderer::render_framebuffer(*sampled);
    double image_difference = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec3 rt_sample = a.radiance_sum[i] - rt_before[i];
      const glm::vec3 sampled_sample = b.radiance_sum[i] - sampled_before[i];
      rt_before[i] = a.radiance_sum[i];
      sampled_before[i] = b.radiance_sum[i];
      rt_sum[i] += glm::dvec3(rt_sample);
      sampled_sum[i] += glm::dvec3(sampled_sample);
      const double d = channel_sum(sampled_sample) - channel_sum(rt_sample);
      diff_sum[i] += d;
      diff_square_sum[i] += d * d;
      image_difference += d;
    }
    image_sum += image_difference;
    image_square_sum += image_difference * image_difference;
    if (pass == 8) error_8 = mean_error(sampled_sum, rt_sum, 8);
    if (pass == 64) error_64 = mean_error(sampled_sum, rt_sum, 64);
  }
  const char* name = lev::method_info(method).name;
  EXPECT_GT(error_8, 0.0) << name << ": the method must actually sample here";
  EXPECT_LE(error_64, 0.45 * error_8) << name;
  // Per pixel, the mean difference within 6 standard errors of zero (the standard error from
  // the measured spread of the differences), plus float rounding of the sums.
  int noisy_pixels = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double mean = diff_sum[i] / kPasses;
    const double variance =
        std::max(0.0, (diff_square_sum[i] - kPasses * mean * mean) / (kPasses - 1));
    const double standard_error = std::sqrt(variance / kPasses);
    const double rounding =
        1e-5 * (1.0 + std::abs(channel_sum(glm::vec3(rt_sum[i] / double(kPasses)))));
    EXPECT_LE(std::abs(mean), 6.0 * standard_error + rounding) << name << ", pixel " << i;
    if (standard_error > 0.0) ++noisy_pixels;
  }
  ASSERT_GT(noisy_pixels, 100) << name;
  const double image_mean = image_sum / kPasses;
  const double image_variance =
      (image_square_sum - kPasses * image_mean * image_mean) / (kPasses - 1);
  EXPECT_LE(std::abs(image_mean), 5.0 * std::sqrt(image_variance / kPasses)) << name;
}

TEST(SamplingRender, LevMcConvergesToRt) {
  expect_converges_to_rt(lev::Method::lev_mc, 0.05f, 1);
  expect_converges_to_rt(lev::Method::lev_mc, 0.5f, 2);
}

TEST(SamplingRender, LightTreeConvergesToRt) {
  expect_converges_to_rt(lev::Method::light_tree, 0.0f, 1);
  expect_converges_to_rt(lev::Method::light_tree, 0.0f, 3);
}

TEST(SamplingRender, ImagesDoNotDependOnThreadsOrTiles) {
  const renderer::Scene scene = random_scene(5);
  const renderer::RayScene rays(scene);
  for (lev::Method method : {lev::Method::lev_mc, lev::Method::light_tree}) {
    for (int k : {1, 3, 4}) {  // 4: the parts are opened (light_sampling.h)
      renderer::RenderSettings rs = sampling_settings(method, 0.05f, 1, 8);
      rs.lights_per_point = k;
      const renderer::Framebuffer one = render_test_image(scene, rays, rs, 3);
      rs.threads = 2;
      const renderer::Framebuffer two = render_test_image(scene, rays, rs, 3);
      rs.tile_size = 5;
      const renderer::Framebuffer tiles = render_test_image(scene, rays, rs, 3);
      EXPECT_TRUE(bitwise_equal(one, two)) << lev::method_info(method).name << " k " << k;
      EXPECT_TRUE(bitwise_equal(one, tiles)) << lev::method_info(method).name << " k " << k;
      EXPECT_EQ(one.radiance_square_sum, two.radiance_square_sum);
    }
  }
}

TEST(SamplingRender, MoreSamplesPerPointDrawMoreLights) {
  const renderer::Scene scene = random_scene(6);
  const renderer::RayScene rays(scene);
  for (lev::Method method : {lev::Method::lev_mc, lev::Method::light_tree}) {
    renderer::RenderSettings rs = sampling_settings(method, 0.05f);
    const renderer::FramebufferTotals one =
        renderer::sum_framebuffer(render_test_image(scene, rays, rs, 1));
    rs.lights_per_point = 4;
    const renderer::FramebufferTotals four =
        renderer::sum_framebuffer(render_test_image(scene, rays, rs, 1));
    EXPECT_GT(four.lights_tested, one.lights_tested) << lev::method_info(method).name;
  }
  renderer::RenderSettings bad = sampling_settings(lev::Method::lev_mc, 0.05f);
  for (int k : {0, -1, lev::kMaxLightsPerPoint + 1}) {
    bad.lights_per_point = k;
    EXPECT_THROW(renderer::make_render_state(scene, rays, bad), std::invalid_argument) << k;
  }
}

TEST(SamplingRender, LevMcAtToleranceZeroEqualsRtBitForBit) {
  for (const renderer::Scene& scene : {random_scene(7), scenes::build_building(3)}) {
    const renderer::RayScene rays(scene);
    const renderer::Framebuffer rt =
        render_test_image(scene, rays, sampling_settings(lev::Method::rt, 0.0f), 2);
    renderer::RenderSettings rs = sampling_settings(lev::Method::lev_mc, 0.0f);
    rs.lights_per_point = 3;
    const renderer::Framebuffer exact = render_test_image(scene, rays, rs, 2);
    EXPECT_TRUE(bitwise_equal(rt, exact)) << scene.name;
  }
}

TEST(SamplingRender, NoiseEstimateIsTheSpreadOfThePasses) {
  const renderer::Scene scene = random_scene(8);
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer fb =
      render_test_image(scene, rays, sampling_settings(lev::Method::light_tree, 0.0f), 16);
  const std::vector<double> noise = renderer::pixel_std_error_pct(fb);
  // A pixel's estimate from its own samples: recompute from the sums with the formula written out.
  double average = 0.0;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    double expected = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double mean = fb.radiance_sum[i][c] / 16.0;
      const double var =
          std::max(0.0, (fb.radiance_square_sum[i][c] / 16.0 - mean * mean) * 16.0 / 15.0);
      expected += std::sqrt(var / 16.0);
    }
    expected *= 100.0 / 3.0;
    EXPECT_NEAR(noise[i], expected, 1e-3 * expected + 1e-6) << i;
    average += noise[i];
  }
  average /= static_cast<double>(noise.size());
  EXPECT_GT(average, 0.0);
  EXPECT_NEAR(renderer::std_error_avg_pct(fb), average, 1e-9 * average);
  // One pass: no spread known.
  const renderer::Framebuffer single =
      render_test_image(scene, rays, sampling_settings(lev::Method::light_tree, 0.0f), 1);
  EXPECT_EQ(renderer::std_error_avg_pct(single), 0.0);
}

}  // namespace
