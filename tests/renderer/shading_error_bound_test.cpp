// The error bound through the shading recursion (shading.cpp, error_bound.h): at every shading
// point the selector's culled irradiance bound times the material's largest response (or, per
// channel, the selector's smaller culled radiance bound), weighed by kr and kt along the path
// exactly as the radiance is. Exact sums on a mirror and a glass slab, and, on random rays
// through mirror and glass spheres, a method that drops half the lights is never further from rt
// than its bound.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_bounds.h"
#include "lev/light_description.h"
#include "lev/methods.h"
#include "renderer/error_bound.h"
#include "renderer/ray_scene.h"
#include "renderer/shading.h"
#include "renderer/shapes.h"
#include "tests/support/error_bound_support.h"

namespace {

struct Traced {
  glm::vec3 radiance{0.0f};
  glm::vec3 bound{0.0f};
};

Traced trace(const renderer::Scene& scene, const renderer::RayScene& rays,
             const lev::LightSelector& selector, const renderer::Ray& ray, int max_depth = 5) {
  lev::SelectorScratch scratch;
  renderer::TraceContext context{scene, rays, selector, scratch, max_depth};
  context.compute_error_bound = true;
  renderer::PathCounters counters;
  Traced t;
  t.radiance = renderer::trace_radiance(context, ray, 0, counters);
  t.bound = counters.error_bound;
  return t;
}

// One prototype holding a quad per entry, each with its own material.
struct Quad {
  glm::vec3 corner, edge_u, edge_v;
  renderer::Material material;
};
renderer::Scene quad_scene(const std::vector<Quad>& quads) {
  renderer::Scene scene;
  renderer::Prototype prototype;
  for (const Quad& q : quads) {
    renderer::TriangleMesh mesh;
    mesh.material = static_cast<std::uint32_t>(scene.materials.size());
    scene.materials.push_back(q.material);
    renderer::add_quad(mesh, q.corner, q.edge_u, q.edge_v);
    prototype.meshes.push_back(mesh);
  }
  scene.geometry.prototypes.push_back(prototype);
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  return scene;
}

// A wall across the y axis at y, facing it from both sides (quads are two-sided).
Quad wall_at(float y, const renderer::Material& material) {
  return {{-5.0f, y, -5.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 10.0f}, material};
}

renderer::Material matte_wall() {
  renderer::Material m;
  m.colour = {0.2f, 0.6f, 0.9f};
  m.kd = 0.5f;
  m.ks = 0.25f;
  return m;
}

void expect_near(const glm::vec3& got, const glm::vec3& want) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-6f * (1.0f + want[c])) << "channel " << c;
}

const renderer::Ray kAlongY{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};

TEST(ShadingErrorBound, AMirrorAddsTheReflectedPointWeighedByKr) {
  renderer::Material mirror;
  mirror.colour = {1.0f, 0.5f, 0.25f};
  mirror.kd = 0.1f;
  mirror.ks = 0.2f;
  mirror.kr = 0.7f;
  // The ray meets the mirror at y = 5 head on and comes back to the wall behind it at y = -5.
  const renderer::Scene scene = quad_scene({wall_at(5.0f, mirror), wall_at(-5.0f, matte_wall())});
  const renderer::RayScene rays(scene);
  const levrt_test::UnitCulledSelector unit;
  const glm::vec3 mirror_response = renderer::largest_response(mirror);
  const glm::vec3 wall_response = renderer::largest_response(matte_wall());
  expect_near(mirror_response, glm::vec3(0.1f, 0.05f, 0.025f) + 0.2f);
  expect_near(trace(scene, rays, unit, kAlongY).bound, mirror_response + 0.7f * wall_response);
  // At depth 0 the reflection is not traced, and neither is its bound.
  expect_near(trace(scene, rays, unit, kAlongY, 0).bound, mirror_response);
  // The bound is the culled irradiance times the response: a culled bound of 1 is the unit.
  expect_near(renderer::shading_error_bound(mirror, glm::vec3(2.0f, 0.0f, 4.0f)),
              glm::vec3(2.0f, 0.0f, 4.0f) * mirror_response);
}

TEST(ShadingErrorBound, GlassAddsBothOfItsFacesAndWhatIsBehindWeighedByKt) {
  renderer::Material glass;
  glass.kd = 0.1f;
  glass.ks = 0.3f;
  glass.kt = 0.8f;
  // A slab from y = 2 to y = 3 met head on: the front face (weight 1), the back face from inside
  // (kt) and the wall behind (kt^2); a straight ray refracts straight.
  const renderer::Scene scene =
      quad_scene({wall_at(2.0f, glass), wall_at(3.0f, glass), wall_at(8.0f, matte_wall())});
  const renderer::RayScene rays(scene);
  const levrt_test::UnitCulledSelector unit;
  const glm::vec3 glass_response = renderer::largest_response(glass);
  const glm::vec3 wall_response = renderer::largest_response(matte_wall());
  expect_near(trace(scene, rays, unit, kAlongY).bound,
              glass_response * (1.0f + 0.8f) + 0.8f * 0.8f * wall_response);
  expect_near(trace(scene, rays, unit, kAlongY, 1).bound, glass_response * (1.0f + 0.8f));
}

TEST(ShadingErrorBound, AMaterialThatReflectsNothingBoundsNothingEvenWhenTheCulledBoundIsInfinite) {
  renderer::Material black;
  black.kd = 0.0f;
  black.ks = 0.0f;
  black.kr = 1.0f;
  const glm::vec3 inf(std::numeric_limits<float>::infinity());
  EXPECT_EQ(renderer::shading_error_bound(black, inf), glm::vec3(0.0f));
  EXPECT_EQ(renderer::shading_error_bound(matte_wall(), inf), inf);
  // On the error scale an infinite bound is the whole range, a channel at most 255 steps.
  EXPECT_DOUBLE_EQ(renderer::error_bound_pct(inf), 100.0);
  EXPECT_DOUBLE_EQ(renderer::error_bound_pct(glm::vec3(0.5f, 0.0f, 2.0f)), 50.0);
}

// A selector's culled radiance bound (CulledRadianceBound) replaces the irradiance route's in the
// channels where it is smaller; unanswered, or NaN in a channel, it changes nothing there.
TEST(ShadingErrorBound, TheSelectorsRadianceBoundReplacesTheLargerIrradianceRoutePerChannel) {
  const renderer::Material wall = matte_wall();
  const glm::vec3 route = renderer::largest_response(wall) * 2.0f;
  lev::CulledRadianceBound radiance;
  radiance.bound = {0.5f * route.x, 2.0f * route.y, std::nanf("")};
  expect_near(renderer::shading_error_bound(wall, glm::vec3(2.0f), radiance), route);
  radiance.bounded = true;
  expect_near(renderer::shading_error_bound(wall, glm::vec3(2.0f), radiance),
              {0.5f * route.x, route.y, route.z});
}

// The bench's per-pixel bounds follow rendered_rgb8's pixels (those with a sample, in order), and
// a pixel's error may exceed its bound by the rounding of one 8-bit step per channel, no more.
TEST(ShadingErrorBound, RenderedBoundsLineUpWithTheSampledPixelsAndAllowOneStepOfRounding) {
  renderer::Framebuffer fb = renderer::make_framebuffer(3, 1);
  fb.samples = {2, 0, 1};
  fb.error_bound_sum = {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(1.0f), glm::vec3(0.0f, 0.0f, 0.5f)};
  const std::vector<double> bounds = renderer::rendered_error_bound_pct(fb);
  ASSERT_EQ(bounds.size(), 2u);
  EXPECT_DOUBLE_EQ(bounds[0], renderer::error_bound_pct(glm::vec3(0.5f, 0.0f, 0.0f)));
  EXPECT_DOUBLE_EQ(bounds[1], renderer::error_bound_pct(glm::vec3(0.0f, 0.0f, 0.5f)));
  const double step = renderer::kErrorBoundRoundingPct;
  EXPECT_TRUE(renderer::within_error_bound(0.0, 0.0));
  EXPECT_TRUE(renderer::within_error_bound(2.0 + step, 2.0));
  EXPECT_FALSE(renderer::within_error_bound(2.0 + step + 1e-6, 2.0));
  EXPECT_FALSE(renderer::within_error_bound(step + 1e-6, 0.0));
}

// A method that shadow-tests the lights of even index (as rt would) and drops the others,
// reporting their exact summed irradiance as its culled bound.
class DropOddLights final : public lev::LightSelector {
 public:
  explicit DropOddLights(const lev::LightHierarchy& hierarchy)
      : lights_(lev::flatten_lights(hierarchy)) {}
  glm::vec3 direct_radiance(lev::ShadingPoint& point, lev::SelectorScratch& scratch,
                            lev::SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override {
    const glm::vec3 x = point.position();
    glm::dvec3 dropped(0.0);
    std::size_t index = 0;
    const glm::vec3 sum = lev::sum_visible_lights(
        lights_,
        [&](const lev::Light& light) {
          const bool keep = index++ % 2 == 0;
          if (!keep) dropped += glm::dvec3(lev::irradiance(light, x));
          return keep && lev::is_important(light, x, 0.0f);
        },
        point, counters, scratch.cancel);
    if (culled_irradiance_bound) *culled_irradiance_bound = lev::round_up_sum(dropped);
    return sum;
  }

 private:
  std::vector<lev::Light> lights_;
};

renderer::Scene mirror_and_glass_scene(std::mt19937_64& engine) {
  const auto uniform = [&](float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine);
  };
  renderer::Scene scene;
  scene.materials = {matte_wall(), levrt_test::pure_mirror(), levrt_test::clear_glass()};
  renderer::Prototype prototype;
  renderer::TriangleMesh ground;
  renderer::add_quad(ground, {-10, -10, 0}, {20, 0, 0}, {0, 20, 0});
  prototype.meshes.push_back(ground);
  renderer::TriangleMesh walls;
  walls.material = 1;
  renderer::add_quad(walls, {-10, 10, 0}, {20, 0, 0}, {0, 0, 8});
  prototype.meshes.push_back(walls);
  prototype.spheres.push_back({{-2.5f, 0.0f, 1.5f}, 1.5f, 1});
  prototype.spheres.push_back({{2.5f, 0.5f, 1.5f}, 1.5f, 2});
  scene.geometry.prototypes.push_back(prototype);
  scene.geometry.instances.push_back({0, lev::Similarity{}});
  std::vector<lev::LightDescriptionNode> lights;
  for (int i = 0; i < 40; ++i) {
    const glm::vec3 p(uniform(-8, 8), uniform(-8, 8), uniform(0.5f, 6.0f));
    const glm::vec3 intensity(uniform(0.05f, 2.0f), uniform(0.05f, 2.0f), uniform(0.05f, 2.0f));
    if (i % 3 == 0) {
      lights.push_back(lev::light_node(
          lev::make_spot_light(p, glm::normalize(glm::vec3(uniform(-1, 1), uniform(-1, 1), -1.0f)),
                               intensity, uniform(0.2f, 3.1f), uniform(0.0f, 10.0f))));
    } else {
      lights.push_back(lev::light_node(lev::make_point_light(p, intensity)));
    }
  }
  scene.light_description.root = lev::union_node(std::move(lights));
  scene.lights = lev::build_hierarchy(scene.light_description);
  return scene;
}

TEST(ShadingErrorBound, DroppingLightsStaysWithinTheBoundThroughMirrorsAndGlass) {
  std::mt19937_64 engine(11);
  const auto uniform = [&](float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine);
  };
  int rays_with_error = 0, rays_needing_the_recursion = 0;
  for (int s = 0; s < 3; ++s) {
    const renderer::Scene scene = mirror_and_glass_scene(engine);
    const renderer::RayScene rays(scene);
    const auto rt = lev::make_selector(scene.lights, {lev::reference_method(), 0.0f});
    const DropOddLights drop(scene.lights);
    for (int i = 0; i < 400; ++i) {
      const glm::vec3 origin(uniform(-6, 6), uniform(-9, -4), uniform(1, 6));
      const glm::vec3 target(uniform(-4, 4), uniform(-1, 4), uniform(0, 3));
      const renderer::Ray ray{origin, glm::normalize(target - origin)};
      const Traced exact = trace(scene, rays, *rt, ray);
      const Traced dropped = trace(scene, rays, drop, ray);
      const Traced first_hit_only = trace(scene, rays, drop, ray, 0);
      EXPECT_EQ(exact.bound, glm::vec3(0.0f));
      for (int c = 0; c < 3; ++c) {
        const float error = std::abs(dropped.radiance[c] - exact.radiance[c]);
        // Room for the float rounding of the two radiance sums.
        EXPECT_LE(error, dropped.bound[c] + 1e-5f * (1.0f + exact.radiance[c]))
            << "scene " << s << " ray " << i;
        if (error > 1e-4f) {
          ++rays_with_error;
          if (error > first_hit_only.bound[c]) ++rays_needing_the_recursion;
        }
      }
    }
  }
  // Not vacuous: lights were missed, and often only the reflected or refracted bound covers them.
  EXPECT_GT(rays_with_error, 100);
  EXPECT_GT(rays_needing_the_recursion, 10);
}

}  // namespace
