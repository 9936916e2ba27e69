// The walk's culled irradiance bound (find_important_lights with a bound requested) against brute
// force: at random points and at the lights of random instanced scenes, for tolerances from 0 to
// huge, it is never below the summed irradiance of the lights the walk did not return; it is 0 at
// tolerance 0; asking for it changes nothing else. The selectors pass it on: rt 0, lev the walk's,
// ast the irradiance of the lights it estimated instead of testing. The culled radiance bound
// (CulledRadianceBound) at random Phong surfaces is never below the brute-force unshadowed
// radiance of the lights not returned, and stays below saturation among culled lights where the
// irradiance bound times the largest response does not.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "lev/selector_ast.h"
#include "lev/selector_lev.h"
#include "lev/selector_rt.h"
#include "tests/lev/open_point.h"
#include "tests/lev/phong_point.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::OpenPoint;
using lev_test::PhongPoint;
using lev_test::Random;

const float kTolerances[] = {0.0f, 1e-3f, 1e-2f, 0.1f, 1e30f};

// The summed irradiance of the world lights that are not important at x.
glm::dvec3 brute_force_culled(const std::vector<lev::Light>& world_lights, const glm::vec3& x,
                              float tolerance) {
  glm::dvec3 sum(0.0);
  for (const lev::Light& l : world_lights) {
    if (!lev::is_important(l, x, tolerance)) sum += glm::dvec3(lev::irradiance(l, x));
  }
  return sum;
}

std::vector<glm::vec3> query_points(Random& r, const std::vector<lev::Light>& world_lights) {
  std::vector<glm::vec3> points;
  for (int k = 0; k < 40; ++k)
    points.push_back({r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-15, 15)});
  points.push_back(1e4f * r.direction());
  for (std::size_t i = 0; i < world_lights.size(); i += 3) {
    points.push_back(world_lights[i].position);
    points.push_back(world_lights[i].position + 0.01f * r.direction());
  }
  return points;
}

// A query of the property tests: a random instanced scene (its hierarchy, its lights in world
// space, its random stream and scratch), a tolerance, its volumes and a point.
struct Query {
  std::uint64_t seed;
  Random& r;
  const lev::LightHierarchy& h;
  const std::vector<lev::Light>& world_lights;
  lev::WalkScratch& scratch;
  float tau;
  const lev::ExtentVolumes& volumes;
  glm::vec3 x;
  std::string context() const {
    return "seed " + std::to_string(seed) + " tau " + std::to_string(tau) + " x (" +
           std::to_string(x.x) + ", " + std::to_string(x.y) + ", " + std::to_string(x.z) + ")";
  }
};

// Calls check for every query point of seeds 1..seeds at every tolerance of kTolerances.
template <typename Check>
void for_each_query(std::uint64_t seeds, Check check) {
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    const std::vector<glm::vec3> points = query_points(r, world_lights);
    lev::WalkScratch scratch;
    for (const float tau : kTolerances) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      for (const glm::vec3& x : points)
        check(Query{seed, r, h, world_lights, scratch, tau, volumes, x});
    }
  }
}

TEST(CulledBound, NeverBelowTheIrradianceOfTheLightsNotReturned) {
  std::uint64_t culled_points = 0, finite_points = 0, tightened_points = 0;
  for_each_query(40, [&](const Query& q) {
    const auto& [seed, r, h, world_lights, scratch, tau, volumes, x] = q;
    const std::string context = q.context();
    std::vector<lev::Light> found, found_without;
    lev::WalkCounters counters, counters_without;
    glm::vec3 bound(-1.0f), tight(-1.0f);
    lev::find_important_lights(h, volumes, tau, x, scratch, found, counters, &bound);
    lev::find_important_lights(h, volumes, tau, x, scratch, found_without, counters_without);
    std::vector<lev::Light> found_tight;
    lev::WalkCounters counters_tight;
    lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch, found_tight, counters_tight,
                                           &tight);
    // The bound is a by-product: the same lights, the same counters.
    lev_test::expect_same_lights(found, found_without, context);
    ASSERT_EQ(counters.nodes_visited, counters_without.nodes_visited) << context;
    lev_test::expect_same_lights(found, found_tight, context);
    ASSERT_EQ(counters.nodes_visited, counters_tight.nodes_visited) << context;
    const glm::dvec3 exact = brute_force_culled(world_lights, x, tau);
    for (int c = 0; c < 3; ++c) {
      ASSERT_FALSE(std::isnan(bound[c])) << context;
      ASSERT_GE(static_cast<double>(bound[c]), exact[c]) << context << ", channel " << c;
      // The tightened bound: still above the exact sum, never above the walk's own.
      ASSERT_FALSE(std::isnan(tight[c])) << context;
      ASSERT_GE(static_cast<double>(tight[c]), exact[c]) << context << ", channel " << c;
      ASSERT_LE(tight[c], bound[c]) << context << ", channel " << c;
    }
    if (std::isinf(bound.x) && std::isfinite(tight.x)) ++tightened_points;
    if (tau == 0.0f) {
      ASSERT_EQ(bound, glm::vec3(0.0f)) << context;
      ASSERT_EQ(tight, glm::vec3(0.0f)) << context;
    }
    if (found.size() < world_lights.size()) ++culled_points;
    if (std::isfinite(bound.x) && exact.x > 0.0) ++finite_points;
  });
  // The property was exercised where lights were culled and the bound said something.
  EXPECT_GT(culled_points, 4000u);
  EXPECT_GT(finite_points, 3000u);
  // Where the walk's bound saturated, the tightened one often says something.
  EXPECT_GT(tightened_points, 20u);
}

// A point beside two lights far apart whose range (1) ends before it: their extent volumes miss
// it, so the subtree holding both is culled, while the box of their positions passes 1.5 from it,
// so the subtree's aggregate bound (which ignores ranges) counts their summed intensity at 1.5:
// the saturation that made pixels read 100 %. The tightened bound opens the subtree and bounds
// each light at its own distance.
TEST(CulledBound, APointBesideACulledSubtreesLightsGetsATightBound) {
  lev::Light left = lev::make_point_light({-10.0f, 0.0f, 0.0f}, glm::vec3(0.5f, 0.5f, 0.0f));
  lev::Light right = lev::make_point_light({10.0f, 0.0f, 0.0f}, glm::vec3(0.5f, 0.25f, 0.0f));
  left.range = right.range = 1.0f;
  lev::LightDescription tree;
  tree.masters.push_back(lev::union_node({lev::light_node(left), lev::light_node(right)}));
  tree.root = lev::union_node(
      {lev::affine_node(lev::make_translation(glm::vec3(0.0f)), lev::instance_node(0)),
       lev::light_node(lev::make_point_light({0.0f, 50.0f, 0.0f}, glm::vec3(0.01f)))});
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const float tau = 0.01f;
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
  const glm::vec3 x(0.0f, 0.0f, 1.5f);
  lev::WalkScratch scratch;
  lev::WalkCounters counters;
  std::vector<lev::Light> found;
  glm::vec3 coarse, tight;
  lev::find_important_lights(h, volumes, tau, x, scratch, found, counters, &coarse);
  EXPECT_TRUE(found.empty());
  lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch, found, counters, &tight);
  EXPECT_TRUE(found.empty());
  // Each light bounded by its intensity over its own distance squared (its aggregate ignores
  // the range), plus the far light's exact irradiance.
  const glm::vec3 each =
      (left.intensity + right.intensity) / 102.25f + glm::vec3(0.01f / (48.5f * 48.5f));
  for (int c = 0; c < 2; ++c) {
    EXPECT_LE(tight[c], each[c] * 1.01f) << c;
    EXPECT_GT(coarse[c], 20.0f * tight[c]) << c;
  }
  // The selector `lev` reports the tightened bound.
  OpenPoint point(x);
  lev::SelectorScratch selector_scratch;
  lev::SelectionCounters selection;
  glm::vec3 reported;
  lev::LevSelector(h, tau).direct_radiance(point, selector_scratch, selection, &reported);
  EXPECT_EQ(reported, tight);
}

// A random Phong surface at x: any normal and viewer, a diffuse colour, a specular lobe or none.
PhongPoint random_surface(Random& r, const glm::vec3& x) {
  const glm::vec3 diffuse(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1));
  const float specular = r.integer(0, 1) == 0 ? 0.0f : r.uniform(0, 1);
  return PhongPoint(x, r.direction(), r.direction(), diffuse, specular, r.uniform(0.0f, 100.0f));
}

TEST(CulledBound, RadianceBoundNeverBelowTheUnshadowedRadianceOfTheLightsNotReturned) {
  std::uint64_t answered = 0, tighter = 0, ten_times_tighter = 0;
  for_each_query(20, [&](const Query& q) {
    const auto& [seed, r, h, world_lights, scratch, tau, volumes, x] = q;
    const std::string context = q.context();
    const PhongPoint point = random_surface(r, x);
    std::vector<lev::Light> found, found_asked;
    lev::WalkCounters counters, counters_asked;
    glm::vec3 irradiance(-1.0f), irradiance_asked(-1.0f);
    lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch, found, counters,
                                           &irradiance);
    lev::CulledRadianceBound radiance;
    radiance.surface = point.surface_response();
    scratch.radiance = &radiance;
    lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch, found_asked, counters_asked,
                                           &irradiance_asked);
    scratch.radiance = nullptr;
    // A by-product: the same lights and counters; the irradiance bound, summed over the
    // radiance bound's parts, is still certified.
    lev_test::expect_same_lights(found, found_asked, context);
    ASSERT_EQ(counters.nodes_visited, counters_asked.nodes_visited) << context;
    ASSERT_TRUE(radiance.bounded) << context;
    ++answered;
    const glm::dvec3 exact = lev::culled_radiance_brute_force(world_lights, point, tau);
    const glm::dvec3 exact_irradiance = brute_force_culled(world_lights, x, tau);
    const glm::vec3 coarse = irradiance * lev::largest_response(point.surface_response());
    for (int c = 0; c < 3; ++c) {
      ASSERT_FALSE(std::isnan(irradiance_asked[c])) << context;
      ASSERT_GE(static_cast<double>(irradiance_asked[c]), exact_irradiance[c])
          << context << ", channel " << c;
      ASSERT_FALSE(std::isnan(radiance.bound[c])) << context;
      ASSERT_GE(static_cast<double>(radiance.bound[c]), exact[c]) << context << ", channel " << c;
    }
    if (lev::brightest(radiance.bound) < lev::brightest(coarse)) ++tighter;
    if (10.0f * lev::brightest(radiance.bound) < lev::brightest(coarse)) ++ten_times_tighter;
    if (tau == 0.0f) {
      ASSERT_EQ(radiance.bound, glm::vec3(0.0f)) << context;
    }
  });
  EXPECT_GT(answered, 4000u);
  // The check can fail: the bound is often below the irradiance route's, and often far below.
  EXPECT_GT(tighter, answered / 2);
  EXPECT_GT(ten_times_tighter, answered / 5);
}

// A ceiling of 16 point lights 3 above a shiny floor, instanced as one subtree: each light's
// extent volume stops short of the floor, so at the point below their centre the whole subtree
// is culled. Their irradiance (even the exact one) times the material's largest response
// saturates a pixel; counted light by light with the cosine toward each and the narrow specular
// lobe, what they can add is a fifth of it, and the radiance bound says so.
TEST(CulledBound, AShinyFloorUnderCulledCeilingLightsGetsARadianceBoundFarBelowSaturation) {
  const float tau = 0.3f;
  std::vector<lev::LightDescriptionNode> ceiling;
  for (const float cx : {-6.0f, -2.0f, 2.0f, 6.0f}) {
    for (const float cy : {-6.0f, -2.0f, 2.0f, 6.0f})
      ceiling.push_back(lev::light_node(lev::make_point_light({cx, cy, 3.0f}, glm::vec3(2.4f))));
  }
  lev::LightDescription tree;
  tree.masters.push_back(lev::union_node(ceiling));
  tree.root = lev::union_node(
      {lev::affine_node(lev::make_translation(glm::vec3(0.0f)), lev::instance_node(0)),
       lev::light_node(lev::make_point_light({0.0f, 50.0f, 0.0f}, glm::vec3(0.01f)))});
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
  const glm::vec3 x(0.0f);
  const PhongPoint point(x, {0.0f, 0.0f, 1.0f}, glm::normalize(glm::vec3(1.0f, 0.0f, 0.2f)),
                         glm::vec3(0.3f), 0.7f, 50.0f);
  lev::WalkScratch scratch;
  lev::WalkCounters counters;
  std::vector<lev::Light> found;
  glm::vec3 irradiance;
  lev::CulledRadianceBound radiance;
  radiance.surface = point.surface_response();
  scratch.radiance = &radiance;
  lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch, found, counters, &irradiance);
  EXPECT_TRUE(found.empty());
  ASSERT_TRUE(radiance.bounded);
  const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
  const glm::dvec3 exact_radiance = lev::culled_radiance_brute_force(world_lights, point, tau);
  const glm::dvec3 exact_irradiance = brute_force_culled(world_lights, x, tau);
  const glm::vec3 largest = lev::largest_response(point.surface_response());
  for (int c = 0; c < 3; ++c) {
    // The irradiance route saturates (a channel's error counts at most 1), even exactly.
    EXPECT_GT(exact_irradiance[c] * largest[c], 1.0) << c;
    EXPECT_GE(irradiance[c] * largest[c], exact_irradiance[c] * largest[c]) << c;
    // The radiance bound holds, and is within a small factor of the truth.
    EXPECT_GE(static_cast<double>(radiance.bound[c]), exact_radiance[c]) << c;
    EXPECT_LT(radiance.bound[c], 0.3f) << c;
    EXPECT_LT(radiance.bound[c], 2.0 * exact_radiance[c]) << c;
  }
  // The selector `lev` answers the request with the walk's bound, and `lev_bounded` (whose walk
  // keeps its culled sum within the tolerance) leaves it unanswered.
  lev::SelectorScratch selector_scratch;
  lev::SelectionCounters selection;
  glm::vec3 reported_irradiance;
  lev::CulledRadianceBound reported;
  selector_scratch.culled_radiance = &reported;
  PhongPoint shaded = point;
  lev::LevSelector(h, tau).direct_radiance(shaded, selector_scratch, selection,
                                           &reported_irradiance);
  EXPECT_TRUE(reported.bounded);
  EXPECT_EQ(reported.bound, radiance.bound);
  EXPECT_EQ(reported_irradiance, irradiance);
  lev::CulledRadianceBound unanswered;
  selector_scratch.culled_radiance = &unanswered;
  lev::LevSelector(h, tau, lev::find_lights_within_budget)
      .direct_radiance(shaded, selector_scratch, selection, &reported_irradiance);
  EXPECT_FALSE(unanswered.bounded);
}

TEST(CulledBound, SelectorsReportWhatTheyLeftOut) {
  Random r(11);
  const lev::LightDescription tree = lev_test::random_instanced_tree(r);
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
  const lev::RtSelector rt(h);
  for (const float tau : kTolerances) {
    const lev::LevSelector lev_selector(h, tau);
    const lev::AstSelector ast(h, tau);
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
    for (int k = 0; k < 50; ++k) {
      const glm::vec3 x(r.uniform(-30, 30), r.uniform(-30, 30), r.uniform(-10, 10));
      OpenPoint point(x);
      lev::SelectorScratch scratch;
      lev::SelectionCounters counters;
      glm::vec3 bound(-1.0f);
      rt.direct_radiance(point, scratch, counters, &bound);
      EXPECT_EQ(bound, glm::vec3(0.0f));
      // lev: the walk's tightened bound, and the radiance is the same with or without asking for
      // it.
      const glm::vec3 radiance = lev_selector.direct_radiance(point, scratch, counters, &bound);
      EXPECT_EQ(radiance, lev_selector.direct_radiance(point, scratch, counters));
      std::vector<lev::Light> found;
      lev::WalkCounters walk_counters;
      glm::vec3 walk_bound;
      lev::find_important_lights_tight_bound(h, volumes, tau, x, scratch.walk, found, walk_counters,
                                             &walk_bound);
      EXPECT_EQ(bound, walk_bound);
      // ast: what it estimated instead of testing; everything at tolerance 0, nothing at a huge
      // one.
      ast.direct_radiance(point, scratch, counters, &bound);
      const glm::dvec3 all =
          brute_force_culled(world_lights, x, std::numeric_limits<float>::infinity());
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(bound[c], 0.0f);
        EXPECT_LE(static_cast<double>(bound[c]), all[c] * (1.0 + 1e-6) + 1e-30);
      }
      if (tau == 0.0f) {
        EXPECT_EQ(bound, glm::vec3(0.0f));
      }
      if (tau == 1e30f) {
        for (int c = 0; c < 3; ++c) EXPECT_GE(static_cast<double>(bound[c]), all[c]);
      }
    }
  }
}

}  // namespace
