// Rendering at the extremes: lights of absurd intensity, lights resting on surfaces, degenerate
// spotlights and tolerances and relative errors at both ends. No Inf or NaN may reach a pixel of
// any method, every method's image is the same on one thread and on two, its certified bound
// holds against `rt`, and every method at its exact setting (`lev` and its kin at tolerance 0,
// `lightcuts` and `lev_cut` at relative error 0) still equals `rt` bit for bit.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/light_bvh.h"
#include "lev/light_description.h"
#include "renderer/pixel_noise.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "renderer/shapes.h"
#include "tests/support/framebuffer_compare.h"

namespace {

// The extreme scenes' 20x20 floor, at z = 0 around the origin.
renderer::TriangleMesh twenty_metre_floor() {
  renderer::TriangleMesh floor;
  renderer::add_quad(floor, {-10, -10, 0}, {20, 0, 0}, {0, 20, 0});
  return floor;
}

// The pixels whose certified error bound is not 0.
int pixels_bounded_above_zero(const renderer::Framebuffer& fb) {
  int count = 0;
  for (const glm::vec3& bound : fb.error_bound_sum)
    if (bound != glm::vec3(0.0f)) ++count;
  return count;
}

// A 20x20 floor with a 2x2x2 box on it, the box of material `box_material`.
renderer::Prototype floor_and_box(std::uint32_t box_material) {
  renderer::Prototype room;
  room.meshes.push_back(twenty_metre_floor());
  renderer::TriangleMesh box;
  box.material = box_material;
  renderer::add_box(box, {-2, -2, 0}, {0, 0, 2});
  room.meshes.push_back(box);
  return room;
}

renderer::Scene extreme_scene() {
  renderer::Scene scene;
  scene.name = "extremes";
  scene.materials.push_back({});  // diffuse grey
  renderer::Material mirror;
  mirror.ks = 0.5f;
  mirror.kr = 0.5f;
  scene.materials.push_back(mirror);
  renderer::Material glass;
  glass.kd = 0.1f;
  glass.kt = 0.8f;
  scene.materials.push_back(glass);
  renderer::Prototype room = floor_and_box(1);
  room.spheres.push_back({{3, 1, 1}, 1.0f, 2});
  scene.geometry.prototypes.push_back(room);
  scene.geometry.instances.push_back({0, lev::Similarity{}});

  const float big = std::numeric_limits<float>::max();
  std::vector<lev::LightDescriptionNode> lights;
  lights.push_back(lev::light_node(lev::make_point_light({0, 4, 3}, {2, 2, 2})));
  lights.push_back(lev::light_node(lev::make_point_light({5, 5, 0}, {1, 1, 1})));  // on the floor
  lights.push_back(
      lev::light_node(lev::make_point_light({-1, -1, 2}, {1, 1, 1})));  // on the box top
  lights.push_back(lev::light_node(lev::make_point_light({4, -4, 2}, {0, 0, 0})));  // dark
  lights.push_back(
      lev::light_node(lev::make_point_light({-6, 6, 1}, {1e-30f, 0, 0})));  // negligible
  lights.push_back(lev::light_node(lev::make_point_light({6, -6, 0.5f}, {1e30f, 1e30f, 0})));
  lights.push_back(lev::light_node(lev::make_point_light({-7, 0, 0.1f}, {big, big, big})));
  const float angles[] = {0.0f, 1e-5f, 1.5707964f, 3.1415927f};
  const float dropoffs[] = {0.0f, 10000.0f};
  int i = 0;
  for (float a : angles) {
    for (float p : dropoffs) {
      lights.push_back(lev::light_node(
          lev::make_spot_light({-8.0f + 2.0f * i, 8, 4}, {0, 0, -1}, {5, 5, 5}, a, p)));
      ++i;
    }
  }
  scene.light_description.root = lev::union_node(std::move(lights));
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -18, 9};
  scene.camera.target = {0, 0, 0};
  return scene;
}

renderer::Framebuffer render_extreme(renderer::Scene& scene, const renderer::RayScene& rays,
                                     lev::Method method, float tau, float relative_error = 0.02f,
                                     int threads = 0) {
  renderer::RenderSettings rs;
  rs.width = 96;
  rs.height = 72;
  rs.method = method;
  rs.tolerance = tau;
  rs.relative_error = relative_error;
  rs.threads = threads;
  rs.compute_error_bound = true;
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::render_framebuffer(*state);
}

// The pixels and their noise estimate (two passes): a sample near the largest float / 2^17 squared
// past the float range in the variance sum, so the stats printed a noise of inf.
void expect_finite(const renderer::Framebuffer& fb, const std::string& label) {
  for (const glm::vec3& c : fb.radiance_sum) {
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(c[k]) && c[k] >= 0.0f) << label;
  }
  for (std::size_t i = 0; i < fb.samples.size(); ++i) {
    ASSERT_TRUE(std::isfinite(renderer::pixel_std_error(fb, i))) << label << ", pixel " << i;
  }
}

// The settings a method is rendered at here: each tolerance for a method that reads it, each
// relative error for one that reads that, the defaults for the rest.
struct ExtremeSetting {
  float tolerance;
  float relative_error;
};
std::vector<ExtremeSetting> extreme_settings(const lev::MethodInfo& info) {
  const float tiny = std::numeric_limits<float>::denorm_min();
  std::vector<ExtremeSetting> settings;
  if (info.uses_tolerance) {
    for (float tau :
         {0.0f, tiny, 1e-30f, 0.01f, 1.0f, 1e30f, std::numeric_limits<float>::infinity()})
      settings.push_back({tau, 0.02f});
  }
  if (info.uses_relative_error) {
    for (float rel : {0.0f, tiny, 1e-7f, 0.02f, 0.9999999f, 1.0f}) settings.push_back({0.01f, rel});
  }
  if (settings.empty()) settings.push_back({0.01f, 0.02f});
  return settings;
}

std::string extreme_label(const lev::MethodInfo& info, const ExtremeSetting& setting) {
  return std::string(info.name) + " tolerance " + std::to_string(setting.tolerance) +
         " relative error " + std::to_string(setting.relative_error);
}

// Every method: light_tree's and lev_mc's descents weighed a subtree whose summed intensity
// overflowed to +inf (the largest-float lights) by inf, and drew with probability inf / inf:
// NaN pixels.
TEST(Extremes, NoInfOrNaNReachesAPixel) {
  renderer::Scene scene = extreme_scene();
  const renderer::RayScene rays(scene);
  for (const lev::MethodInfo& info : lev::method_table()) {
    for (const ExtremeSetting& setting : extreme_settings(info)) {
      expect_finite(render_extreme(scene, rays, info.id, setting.tolerance, setting.relative_error),
                    extreme_label(info, setting));
    }
  }
}

// Determinism (every method, samplers included, on one thread and on two), the certified bound
// against rt (per sample and channel, error_bound.h), and the exact settings equal to rt.
TEST(Extremes, EveryMethodIsDeterministicWithinItsBoundAndExactAtZero) {
  renderer::Scene scene = extreme_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  for (const lev::MethodInfo& info : lev::method_table()) {
    for (const ExtremeSetting& setting : extreme_settings(info)) {
      const std::string label = extreme_label(info, setting);
      const renderer::Framebuffer one =
          render_extreme(scene, rays, info.id, setting.tolerance, setting.relative_error, 1);
      const renderer::Framebuffer two =
          render_extreme(scene, rays, info.id, setting.tolerance, setting.relative_error, 2);
      EXPECT_TRUE(bitwise_equal(one, two)) << label;
      // AST at 0 tests every light but sums them in its own order: equal to rt up to rounding.
      const bool exact = info.id != lev::Method::ast &&
                         ((info.uses_tolerance && setting.tolerance == 0.0f) ||
                          (info.uses_relative_error && setting.relative_error == 0.0f));
      if (exact) {
        EXPECT_TRUE(bitwise_equal(one, rt)) << label;
      }
      if (info.stochastic) continue;
      int over = 0;
      for (std::size_t i = 0; i < rt.radiance_sum.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
          const float error = std::abs(one.radiance_sum[i][c] - rt.radiance_sum[i][c]);
          // Rounding of the two sums (their summation orders differ) on top of the bound.
          const float rounding = 1e-6f * std::abs(rt.radiance_sum[i][c]);
          if (error > one.error_bound_sum[i][c] * 1.0001f + rounding) ++over;
        }
      }
      EXPECT_EQ(over, 0) << label;
    }
  }
}

// Radiance past the float range from valid inputs: lights of 1e36 (a scene file's 1e12 under
// scales of 1e12) on a surface of kd, colour and ks 1e3. The irradiance is clamped to the largest
// float, but times the response it overflowed: AST estimated an untested light of +inf radiance
// by a hit ratio of 0 (NaN pixels, black where rt is white), and two samples near the largest
// float summed to +inf in the pixel (rt's too).
renderer::Scene huge_radiance_scene() {
  renderer::Scene scene;
  scene.name = "huge radiance";
  renderer::Material bright;
  bright.colour = glm::vec3(1e3f);
  bright.kd = 1e3f;
  bright.ks = 1e3f;
  bright.shininess = 0.0f;
  scene.materials.push_back(bright);
  scene.geometry.prototypes.push_back(floor_and_box(0));
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  std::vector<lev::LightDescriptionNode> lights;
  lights.push_back(lev::light_node(lev::make_point_light({0, 0, 3}, glm::vec3(1e36f))));
  lights.push_back(lev::light_node(lev::make_point_light({0, 1, 3}, {1e36f, 0, 0})));
  lights.push_back(lev::light_node(lev::make_point_light({2, 2, 2}, glm::vec3(1.0f))));
  scene.light_description.root = lev::union_node(std::move(lights));
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -18, 9};
  scene.camera.target = {0, 0, 0};
  return scene;
}

TEST(Extremes, RadianceBeyondTheFloatRangeStaysFiniteInEveryMethod) {
  renderer::Scene scene = huge_radiance_scene();
  const renderer::RayScene rays(scene);
  for (const lev::MethodInfo& info : lev::method_table()) {
    for (const ExtremeSetting& setting : extreme_settings(info)) {
      const renderer::Framebuffer fb =
          render_extreme(scene, rays, info.id, setting.tolerance, setting.relative_error);
      expect_finite(fb, extreme_label(info, setting));
      // The image shows the lit floor white, as rt's does.
      if (info.id == lev::Method::ast && setting.tolerance > 0.0f &&
          std::isfinite(setting.tolerance)) {
        const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
        EXPECT_EQ(renderer::framebuffer_rgb8(fb), renderer::framebuffer_rgb8(rt))
            << extreme_label(info, setting);
      }
    }
  }
}

// AST tests its candidates until their untested rest is below the tolerance. It kept that rest as
// a running difference of doubles, which a huge potential swamps: a light of 1e36 hidden behind
// a wall, and lights of 1 beside it, left 1e36 + 0.3 + 0.3 - 1e36 = 0 (then less than 0) with
// lights of 0.3 untested, so testing stopped there and they were estimated from hit ratios, at
// tolerance 0 too: 14 % of a pixel off rt's at tolerance 0, 27 % at 0.001.
renderer::Scene ast_hidden_giant_scene() {
  renderer::Scene scene;
  scene.name = "hidden giant";
  scene.materials.push_back({});
  renderer::Prototype room;
  room.meshes.push_back(twenty_metre_floor());
  renderer::TriangleMesh boxes;
  renderer::add_box(boxes, {-10, 5, 0}, {10, 6, 10});  // the wall before the giant
  std::vector<lev::LightDescriptionNode> lights;
  lights.push_back(lev::light_node(lev::make_point_light({0, 8, 3}, glm::vec3(1e36f))));
  for (int i = 0; i < 6; ++i) {
    const float x = -5.0f + 2.0f * static_cast<float>(i);
    lights.push_back(lev::light_node(lev::make_point_light({x, 0, 2}, glm::vec3(1.0f))));
    // Under a box of its own: seen by no point of the floor.
    lights.push_back(lev::light_node(lev::make_point_light({x, -3, 0.5f}, glm::vec3(1.0f))));
    renderer::add_box(boxes, {x - 0.5f, -3.5f, 0}, {x + 0.5f, -2.5f, 1});
  }
  room.meshes.push_back(boxes);
  scene.geometry.prototypes.push_back(room);
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  scene.light_description.root = lev::union_node(std::move(lights));
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -12, 8};
  scene.camera.target = {0, 0, 0};
  return scene;
}

TEST(Extremes, AstTestsUntilTheTrueRestIsBelowTheToleranceBesideAHugeLight) {
  renderer::Scene scene = ast_hidden_giant_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  // A diffuse floor and nothing else: the direct radiance is the pixel's, and AST's estimate of
  // its untested rest is off by at most that rest.
  for (const float tau : {0.0f, 1e-3f, 1e-2f}) {
    const renderer::Framebuffer ast = render_extreme(scene, rays, lev::Method::ast, tau);
    int over = 0;
    for (std::size_t i = 0; i < rt.radiance_sum.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const float error = std::abs(ast.radiance_sum[i][c] - rt.radiance_sum[i][c]);
        // Two passes, each within the tolerance, and the rounding of two summation orders.
        if (error > 2.0f * tau + 1e-5f * rt.radiance_sum[i][c]) ++over;
      }
    }
    EXPECT_EQ(over, 0) << "tolerance " << tau;
  }
}

// lev_est stands for what lev culls by clusters, each a representative light at its cluster's
// centre. Lights shut in two boxes three units either side of the origin make one cluster at a
// loose tolerance, its representative a unit above the floor between them, where no light
// reaches: seen there, it lit the floor white (pixel error 92 %) where rt's floor is black and
// lev's certified bound of the culled light is a fraction of that. The estimate is now at most
// that bound.
renderer::Scene boxed_lights_scene() {
  renderer::Scene scene;
  scene.name = "boxed lights";
  scene.materials.push_back({});
  renderer::Prototype room;
  room.meshes.push_back(twenty_metre_floor());
  renderer::TriangleMesh boxes;
  renderer::add_box(boxes, {-3.5f, -0.5f, 0.5f}, {-2.5f, 0.5f, 1.5f});
  renderer::add_box(boxes, {2.5f, -0.5f, 0.5f}, {3.5f, 0.5f, 1.5f});
  room.meshes.push_back(boxes);
  scene.geometry.prototypes.push_back(room);
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  std::vector<lev::Light> lights;
  for (const float x : {-3.0f, 3.0f}) {
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 offset(static_cast<float>(k % 2), static_cast<float>(k / 2 % 2),
                             static_cast<float>(k / 4));
      lights.push_back(
          lev::make_point_light(glm::vec3(x, 0, 1) + 0.05f * offset, glm::vec3(0.25f)));
    }
  }
  // A flat list: the hierarchy a scene file gets, whose unions lev_est cuts into clusters.
  scene.light_description.root = lev::build_light_bvh(lights);
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -6, 5};
  scene.camera.target = {0, 0, 0};
  return scene;
}

TEST(Extremes, LevEstNeverEstimatesMoreThanTheBoundOfWhatItCulls) {
  renderer::Scene scene = boxed_lights_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  for (const float tau : {0.2f, 1.0f, 3.0f}) {
    const renderer::Framebuffer lev = render_extreme(scene, rays, lev::Method::lev, tau);
    const renderer::Framebuffer est = render_extreme(scene, rays, lev::Method::lev_est, tau);
    int over = 0;
    for (std::size_t i = 0; i < rt.radiance_sum.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const float error = std::abs(est.radiance_sum[i][c] - rt.radiance_sum[i][c]);
        if (error > lev.error_bound_sum[i][c] * 1.0001f + 1e-6f) ++over;
      }
    }
    EXPECT_EQ(over, 0) << "tolerance " << tau;
  }
}

// Lights with ranges from 1e-30 to 1e30 (points, and smooth spots of 1e-6 to 180 degrees), a flat
// list as a scene file gives it. At tolerance 0 lev's walk culls only lights dark at the point
// (past their ranges) and its image is rt's, but the culled subtrees' aggregate bounds know no
// range: lev certified up to 10 % of error there, and lev_mc drew from those dark lights (to
// no effect) and certified nothing (100 %).
renderer::Scene ranged_lights_scene() {
  renderer::Scene scene;
  scene.name = "ranged lights";
  scene.materials.push_back({});
  scene.geometry.prototypes.push_back(floor_and_box(0));
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  const float point_ranges[] = {1e-30f, 1e-3f, 1.0f, 3.0001f, 1e30f};
  const float spot_ranges[] = {1e-30f, 3.0f, 1e30f};
  const float cones[] = {1.7453292e-8f, 1.5707964f, 3.1415927f, 0.5235988f};
  std::vector<lev::Light> lights;
  for (int i = 0; i < 40; ++i) {
    const float x = 0.3f * static_cast<float>(i) - 7.0f;
    lev::Light point = lev::make_point_light({x, 0, 3}, glm::vec3(1.0f));
    point.range = point_ranges[i % 5];
    lights.push_back(point);
    lev::Light spot =
        lev::make_smooth_spot_light({x, 2, 3}, {0, 0, -1}, glm::vec3(1.0f), 0.0f, cones[i % 4]);
    spot.range = spot_ranges[i % 3];
    lights.push_back(spot);
  }
  scene.light_description.root = lev::build_light_bvh(lights);
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -18, 9};
  scene.camera.target = {0, 0, 0};
  return scene;
}

TEST(Extremes, AtToleranceZeroLevAndLevMcCertifyZeroPastTheLightsRanges) {
  renderer::Scene scene = ranged_lights_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  for (const lev::Method method : {lev::Method::lev, lev::Method::lev_mc}) {
    const renderer::Framebuffer fb = render_extreme(scene, rays, method, 0.0f);
    EXPECT_TRUE(bitwise_equal(fb, rt)) << lev::method_info(method).name;
    EXPECT_EQ(pixels_bounded_above_zero(fb), 0) << lev::method_info(method).name;
    EXPECT_EQ(renderer::sum_framebuffer(fb).lights_tested,
              renderer::sum_framebuffer(rt).lights_tested)
        << lev::method_info(method).name;
  }
}

// A floor lit only from below: every light lies behind the surface the camera sees, so the
// sampling methods' importances are all zero there and they draw nothing. The radiance is rt's
// (the ambient term) and is certified so: the bound said +inf (100 %), as for any sampled estimate.
renderer::Scene lights_under_the_floor_scene() {
  renderer::Scene scene;
  scene.name = "lights under the floor";
  scene.materials.push_back({});
  renderer::Prototype room;
  room.meshes.push_back(twenty_metre_floor());
  scene.geometry.prototypes.push_back(room);
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  std::vector<lev::Light> lights;
  for (int i = 0; i < 16; ++i) {
    const glm::vec3 p(static_cast<float>(i % 4) - 1.5f, static_cast<float>(i / 4) - 1.5f, -2.0f);
    lights.push_back(lev::make_point_light(p, glm::vec3(0.5f)));
  }
  scene.light_description.root = lev::build_light_bvh(lights);
  scene.lights = lev::build_hierarchy(scene.light_description);
  scene.camera.position = {0, -6, 8};
  scene.camera.target = {0, 0, 0};
  return scene;
}

TEST(Extremes, SamplingMethodsCertifyZeroWhereNoLightCanReachThePoint) {
  renderer::Scene scene = lights_under_the_floor_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  for (const lev::Method method : {lev::Method::light_tree, lev::Method::lev_mc}) {
    const renderer::Framebuffer fb = render_extreme(scene, rays, method, 0.01f);
    EXPECT_TRUE(bitwise_equal(fb, rt)) << lev::method_info(method).name;
    EXPECT_EQ(pixels_bounded_above_zero(fb), 0) << lev::method_info(method).name;
  }
}

TEST(Extremes, LevAtToleranceZeroStillEqualsRt) {
  renderer::Scene scene = extreme_scene();
  const renderer::RayScene rays(scene);
  const renderer::Framebuffer rt = render_extreme(scene, rays, lev::Method::rt, 0.0f);
  const renderer::Framebuffer lev = render_extreme(scene, rays, lev::Method::lev, 0.0f);
  ASSERT_EQ(rt.radiance_sum.size(), lev.radiance_sum.size());
  EXPECT_EQ(std::memcmp(rt.radiance_sum.data(), lev.radiance_sum.data(),
                        rt.radiance_sum.size() * sizeof(glm::vec3)),
            0);
  // A denormal tolerance reaches the hierarchy as itself: no light is culled that rt shades
  // except those below it, and none of this scene's lights is that dim except the 1e-30 one.
  const renderer::Framebuffer denormal =
      render_extreme(scene, rays, lev::Method::lev, std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(renderer::framebuffer_rgb8(denormal), renderer::framebuffer_rgb8(rt));
}

TEST(Extremes, InfiniteToleranceTestsNoLight) {
  renderer::Scene scene = extreme_scene();
  const renderer::RayScene rays(scene);
  const auto totals = renderer::sum_framebuffer(
      render_extreme(scene, rays, lev::Method::lev, std::numeric_limits<float>::infinity()));
  EXPECT_EQ(totals.lights_tested, 0u);
  EXPECT_GT(totals.shading_points, 0u);
}

}  // namespace
