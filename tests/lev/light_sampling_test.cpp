// The importance descent (lev/light_sampling.h) on random instanced hierarchies: one descent's
// probabilities over every light sum to 1; every light that can light a point (inside light
// boxes, on spot cone edges, with and without a surface normal) has a non-zero probability; a
// sampled light comes with the probability the enumeration gives it, so the weighted estimator's
// expectation is the exact sum; and the walk's culled parts plus its lights are every light
// that can light the point, once each.
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "lev/hierarchy_cursor.h"
#include "lev/important_lights.h"
#include "lev/light_description.h"
#include "lev/light_hierarchy.h"
#include "lev/light_sampling.h"
#include "lev/selector_lev_mc.h"
#include "lev/selector_rt.h"
#include "tests/lev/open_point.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

// Points where sampling is hard: near and inside light boxes (on a light, beside it), on the
// edge of spot cones (rotated by a few float ulps either way), and anywhere.
std::vector<glm::vec3> hard_points(Random& r, const std::vector<lev::Light>& lights) {
  std::vector<glm::vec3> points;
  for (int i = 0; i < 6; ++i)
    points.push_back({r.uniform(-30, 30), r.uniform(-30, 30), r.uniform(-10, 10)});
  for (int i = 0; i < 6; ++i) {
    const lev::Light& l =
        lights[static_cast<std::size_t>(r.integer(0, static_cast<int>(lights.size()) - 1))];
    points.push_back(l.position);
    points.push_back(l.position + r.direction() * r.uniform(1e-4f, 0.5f));
    if (l.kind == lev::LightKind::spot && l.cos_cone_half_angle > -1.0f &&
        l.cos_cone_half_angle < 1.0f) {
      // A direction at the cone's half-angle from the axis.
      glm::vec3 side = glm::cross(l.direction, r.direction());
      if (glm::dot(side, side) < 1e-6f) continue;
      side = glm::normalize(side);
      const float c = l.cos_cone_half_angle, s = std::sqrt(std::max(0.0f, 1.0f - c * c));
      for (int k = -8; k <= 8;
           ++k) {  // turned off the edge by k float ulps of the angle, either way
        const float turn = 6e-8f * static_cast<float>(k);
        const glm::vec3 edge = (c - turn * s) * l.direction + (s + turn * c) * side;
        for (float d : {0.01f, 1.0f, 7.0f}) points.push_back(l.position + d * edge);
      }
    }
  }
  return points;
}

// Lights straight under unions (no extent volume of their own), instanced under random
// similarities: the descent then weighs each light by itself, in its master's frame.
lev::LightDescription bare_light_description(Random& r) {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> lights;
  const int count = r.integer(2, 6);
  for (int c = 0; c < count; ++c) lights.push_back(lev::light_node(lev_test::random_light(r)));
  tree.masters.push_back(lev::union_node(std::move(lights)));
  std::vector<lev::LightDescriptionNode> roots;
  for (int i = 0; i < 3; ++i)
    roots.push_back(lev::affine_node(lev_test::random_similarity(r), lev::instance_node(0)));
  roots.push_back(lev::light_node(lev_test::random_light(r)));
  tree.root = lev::union_node(std::move(roots));
  return tree;
}

lev::LightDescription random_sampling_tree(Random& r, int scene) {
  return scene % 2 == 0 ? lev_test::random_instanced_tree(r) : bare_light_description(r);
}

using lev_test::same_light_placement;

// What the estimator weighs a light by, on the light's own side of a surface with this normal.
double contribution(const lev::Light& light, const glm::vec3& x, const glm::vec3& normal) {
  const glm::vec3 e = lev::irradiance(light, x);
  double sum = static_cast<double>(e.x) + e.y + e.z;
  if (normal != glm::vec3(0.0f)) {
    const glm::vec3 to_light = light.position - x;
    if (!(glm::dot(normal, to_light) > 0.0f)) sum = 0.0;
  }
  return sum;
}

TEST(LightSampling, ProbabilitiesSumToOneAndReachEveryContributingLight) {
  Random r(20261123);
  int checked_points = 0, contributing = 0;
  for (int scene = 0; scene < 200; ++scene) {
    const lev::LightHierarchy h = lev::build_hierarchy(random_sampling_tree(r, scene));
    const std::vector<lev::Light> flat = lev::flatten_lights(h);
    for (const glm::vec3& x : hard_points(r, flat)) {
      for (const glm::vec3 normal : {glm::vec3(0.0f), r.direction()}) {
        const lev::SamplingPoint at{x, normal};
        std::vector<lev::SampledLight> enumerated;
        lev::light_probabilities(h, lev::whole_hierarchy(h, x), at, enumerated);
        ASSERT_EQ(enumerated.size(), flat.size());
        double total = 0.0, exact = 0.0, expected = 0.0;
        for (std::size_t i = 0; i < flat.size(); ++i) {
          // The descent composes frames as the walk does: the same world lights, bit for bit.
          ASSERT_TRUE(same_light_placement(enumerated[i].light, flat[i]))
              << "scene " << scene << ", light " << i;
          const double p = enumerated[i].probability;
          const double f = contribution(flat[i], x, normal);
          total += p;
          exact += f;
          if (f > 0.0) {
            ++contributing;
            ASSERT_GT(p, 0.0) << "scene " << scene << ", light " << i
                              << " lights the point but cannot be drawn";
            expected += p * (f / p);
          }
        }
        ++checked_points;
        EXPECT_NEAR(total, 1.0, 1e-9);
        EXPECT_NEAR(expected, exact, 1e-9 * exact);
      }
    }
  }
  EXPECT_GT(contributing, 1000);  // the cases above really contain lights that light the points
  EXPECT_GT(checked_points, 500);
}

TEST(LightSampling, DrawnLightsComeWithTheirEnumeratedProbabilityAndFrequency) {
  Random r(7);
  for (int scene = 0; scene < 10; ++scene) {
    const lev::LightHierarchy h = lev::build_hierarchy(random_sampling_tree(r, scene));
    const std::vector<lev::Light> flat = lev::flatten_lights(h);
    const glm::vec3 x(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-5, 5));
    const lev::SamplingPoint at{x, r.direction()};
    std::vector<lev::SampledLight> enumerated;
    lev::light_probabilities(h, lev::whole_hierarchy(h, x), at, enumerated);
    lev::RandomStream random{static_cast<std::uint64_t>(scene) + 1};
    std::vector<double> weights;
    std::vector<int> drawn(flat.size(), 0);
    constexpr int kDraws = 20000;
    for (int d = 0; d < kDraws; ++d) {
      lev::SampledLight s;
      std::uint64_t visited = 0;
      lev::sample_light(h, lev::whole_hierarchy(h, x), at, random, weights, s, visited);
      std::size_t i = 0;
      while (i < flat.size() && !(same_light_placement(flat[i], s.light) &&
                                  enumerated[i].probability == s.probability))
        ++i;
      ASSERT_LT(i, flat.size()) << "a drawn light or its probability is not the enumeration's";
      ++drawn[i];
    }
    // Each light's frequency is binomial: within 5 standard deviations of p * draws.
    for (std::size_t i = 0; i < flat.size(); ++i) {
      const double p = enumerated[i].probability;
      const double sd = std::sqrt(kDraws * p * (1.0 - p));
      EXPECT_NEAR(drawn[i], kDraws * p, 5.0 * sd + 1.0) << "scene " << scene << ", light " << i;
    }
  }
}

TEST(LightSampling, WalkLightsAndCulledPartsAreEveryContributingLightOnce) {
  Random r(99);
  for (int scene = 0; scene < 30; ++scene) {
    const lev::LightHierarchy h = lev::build_hierarchy(random_sampling_tree(r, scene));
    const std::vector<lev::Light> flat = lev::flatten_lights(h);
    const float tolerance = std::pow(10.0f, r.uniform(-4.0f, 1.0f));
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tolerance);
    for (const glm::vec3& x : hard_points(r, flat)) {
      std::vector<lev::Light> important;
      lev::CulledParts culled;
      lev::WalkScratch scratch;
      lev::WalkCounters counters;
      lev::find_important_and_culled(h, volumes, tolerance, x, scratch, important, counters,
                                     culled);
      std::vector<lev::Light> parts = important;
      parts.insert(parts.end(), culled.lights.begin(), culled.lights.end());
      for (const lev::SubtreeRef& subtree : culled.subtrees) {
        std::vector<lev::SampledLight> lights;
        lev::light_probabilities(h, subtree, {x, glm::vec3(0.0f)}, lights);
        for (const lev::SampledLight& l : lights) parts.push_back(l.light);
      }
      for (std::size_t i = 0; i < flat.size(); ++i) {
        int found = 0;
        for (const lev::Light& l : parts) found += same_light_placement(l, flat[i]) ? 1 : 0;
        // Lights of one scene may coincide (instances of one master placed alike): count them too.
        int twins = 0;
        for (const lev::Light& l : flat) twins += same_light_placement(l, flat[i]) ? 1 : 0;
        if (lev::irradiance(flat[i], x) != glm::vec3(0.0f)) {
          EXPECT_EQ(found, twins) << "scene " << scene << ", light " << i;
        } else {
          EXPECT_LE(found, twins);
        }
      }
    }
  }
}

}  // namespace

namespace {

// A layer of point lights on a ceiling (the building's rooms, the hall's rig) seen from a point
// of the ceiling beside it, whose normal faces down: every light arrives at a grazing angle. The
// importance of the layer stays within a small factor of its lights' own (the bound of cos(theta)
// by projection; the sphere around the layer's box would allow cos = 1, hundreds of times too
// much), and every light still has a non-zero probability.
TEST(LightSampling, ALayerSeenEdgeOnWeighsLikeItsLights) {
  std::vector<lev::LightDescriptionNode> layer;
  for (int i = 0; i < 16; ++i) {
    const glm::vec3 p(static_cast<float>(i % 4), static_cast<float>(i / 4), -0.01f);
    layer.push_back(lev::light_node(lev::make_point_light(p, glm::vec3(1.0f))));
  }
  lev::LightDescription tree;
  tree.root = lev::union_node(std::move(layer));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const glm::vec3 normal(0.0f, 0.0f, -1.0f);
  const glm::vec3 beside[] = {{5.0f, 1.5f, 0.0f}, {-2.0f, -2.0f, 0.0f}, {1.5f, 6.0f, 0.0f}};
  for (const glm::vec3& x : beside) {
    const lev::FramePoint at = lev::world_frame_point(x);
    double lights = 0.0;
    std::vector<lev::SampledLight> enumerated;
    lev::light_probabilities(h, lev::whole_hierarchy(h, x), {x, normal}, enumerated);
    ASSERT_EQ(enumerated.size(), 16u);
    for (const lev::SampledLight& l : enumerated) {
      EXPECT_GT(l.probability, 0.0);
      lights += lev::light_importance(l.light, at, normal);
    }
    const double layer_importance = lev::subtree_importance(h, h.root, at, normal);
    EXPECT_GT(layer_importance, 0.0);
    EXPECT_LT(layer_importance, 8.0 * lights) << "at " << x.x << " " << x.y;
  }
}

}  // namespace

namespace {

// A light dark at the point keeps a share of its bound (the edge share: rounding between frames
// might light it), but near the light that bound grows as 1 / d^2: a spot of 390 a millimetre from
// the point, which lies outside its cone, weighed 500,000 times the light of 14 that gave the
// point all its light, so the light was drawn once in 800,000 draws (light_tree's passes did not
// settle where lights rest just above a floor). Its share is now at most kEdgeShare of what the
// lights that do light the point weigh.
TEST(LightSampling, ALightDarkAtThePointDoesNotOutweighTheLightThatLightsIt) {
  // Four units from the origin: the frames' rounding allowance (kFrameRounding) is 4e-4 there, a
  // third of the distance, so the light's bound holds the point.
  const glm::vec3 x(-3.62549f, 3.92723f, 0.00938966f);
  const lev::Light dark = lev::make_smooth_spot_light(
      {-3.62452f, 3.92814f, 0.01f}, glm::normalize(glm::vec3(0.584693f, 0.069255f, -0.808293f)),
      glm::vec3(389.5f), 0.3316f, 1.5707964f);
  const lev::Light lit = lev::make_point_light({0.378078f, -0.562712f, 0.01f}, glm::vec3(14.0f));
  ASSERT_EQ(lev::irradiance(dark, x), glm::vec3(0.0f));
  ASSERT_GT(lev::irradiance(lit, x).x, 0.3f);
  std::vector<lev::LightDescriptionNode> lights;
  lights.push_back(lev::light_node(dark));
  lights.push_back(lev::light_node(lit));
  lev::LightDescription tree;
  tree.root = lev::union_node(std::move(lights));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  for (const glm::vec3& normal : {glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f)}) {
    std::vector<lev::SampledLight> enumerated;
    lev::light_probabilities(h, lev::whole_hierarchy(h, x), {x, normal}, enumerated);
    ASSERT_EQ(enumerated.size(), 2u);
    EXPECT_GT(enumerated[0].probability, 0.0);
    EXPECT_GT(enumerated[1].probability, 0.99) << "normal " << normal.z;
  }
}

}  // namespace

namespace {

// Every light of the parts, subtrees enumerated, with its probability of being drawn when the
// parts are chosen by importance at x (as sampled_radiance chooses them).
std::vector<lev::SampledLight> lights_of_parts(const lev::LightHierarchy& h,
                                               const lev::CulledParts& parts, const glm::vec3& x,
                                               const glm::vec3& normal) {
  std::vector<double> weights;
  double total = 0.0;
  for (const lev::SubtreeRef& s : parts.subtrees) {
    weights.push_back(lev::subtree_importance(
        h, s.node, s.point, glm::transpose(s.world_from_local.rotation) * normal));
    total += weights.back();
  }
  for (const lev::Light& l : parts.lights) {
    weights.push_back(lev::light_importance(l, lev::world_frame_point(x), normal));
    total += weights.back();
  }
  std::vector<lev::SampledLight> out, in_part;
  for (std::size_t i = 0; i < parts.subtrees.size(); ++i) {
    lev::light_probabilities(h, parts.subtrees[i], {x, normal}, in_part);
    for (lev::SampledLight l : in_part) {
      l.probability *= total > 0.0 ? weights[i] / total : 0.0;
      out.push_back(l);
    }
  }
  for (std::size_t i = 0; i < parts.lights.size(); ++i) {
    const double share = total > 0.0 ? weights[parts.subtrees.size() + i] / total : 0.0;
    out.push_back({parts.lights[i], share});
  }
  return out;
}

// Opening the parts whose spots aim apart (the first step of sampled_radiance) keeps every light
// once, stays within its budget, and leaves every light that can light the point drawable, the
// probabilities summing to 1; on scenes whose spots aim every way it does open parts.
TEST(LightSampling, OpeningWidePartsKeepsEveryLightOnceWithinTheBudget) {
  Random r(4242);
  int opened = 0;
  for (int scene = 0; scene < 60; ++scene) {
    const lev::LightHierarchy h = lev::build_hierarchy(random_sampling_tree(r, scene));
    const std::vector<lev::Light> flat = lev::flatten_lights(h);
    const float tolerance = std::pow(10.0f, r.uniform(-4.0f, 1.0f));
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tolerance);
    for (const glm::vec3& x : hard_points(r, flat)) {
      const glm::vec3 normal = scene % 3 == 0 ? glm::vec3(0.0f) : r.direction();
      lev::CulledParts parts;
      if (scene % 2 == 0) {
        parts.subtrees.push_back(lev::whole_hierarchy(h, x));
      } else {
        std::vector<lev::Light> important;
        lev::WalkScratch walk;
        lev::WalkCounters counters;
        lev::find_important_and_culled(h, volumes, tolerance, x, walk, important, counters, parts);
      }
      const std::vector<lev::SampledLight> before = lights_of_parts(h, parts, x, normal);
      const std::size_t parts_before = parts.subtrees.size() + parts.lights.size();
      const std::size_t budget = static_cast<std::size_t>(1) << r.integer(0, 6);
      std::vector<lev::SubtreeRef> queue;
      lev::open_wide_parts(h, parts, budget, queue);
      const std::size_t parts_after = parts.subtrees.size() + parts.lights.size();
      EXPECT_GE(parts_after, parts_before);
      if (parts_before <= budget) {
        EXPECT_LE(parts_after, budget);
      }
      if (parts_after > parts_before) ++opened;
      const std::vector<lev::SampledLight> after = lights_of_parts(h, parts, x, normal);
      ASSERT_EQ(after.size(), before.size()) << "scene " << scene;
      double total = 0.0;
      for (const lev::SampledLight& l : after) {
        int in_before = 0, in_after = 0;
        for (const lev::SampledLight& b : before)
          in_before += same_light_placement(b.light, l.light) ? 1 : 0;
        for (const lev::SampledLight& a : after)
          in_after += same_light_placement(a.light, l.light) ? 1 : 0;
        EXPECT_EQ(in_after, in_before) << "scene " << scene;
        if (contribution(l.light, x, normal) > 0.0) {
          EXPECT_GT(l.probability, 0.0) << "scene " << scene << ": lights the point, no chance";
        }
        total += l.probability;
      }
      if (total > 0.0) {
        EXPECT_NEAR(total, 1.0, 1e-9) << "scene " << scene;
      }
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(opened, 20);
}

// Lights whose summed intensity overflows a float: 64 lights of the largest float (the extremes
// pinned for lev), so the aggregates above them are +inf. The estimator weighed such a part by an
// infinite importance and drew it with probability inf / inf: NaN, and light_tree's and lev_mc's
// pixels were NaN. Every probability stays finite and they sum to 1; the estimate is finite.
TEST(LightSampling, SubtreesWhoseIntensityOverflowsAreDrawnWithFiniteProbabilities) {
  std::vector<lev::LightDescriptionNode> lights;
  for (int i = 0; i < 64; ++i) {
    const glm::vec3 at(static_cast<float>(i % 8), static_cast<float>(i / 8), 5.0f);
    lights.push_back(
        lev::light_node(lev::make_point_light(at, glm::vec3(std::numeric_limits<float>::max()))));
  }
  lev::LightDescription tree;
  tree.root = lev::union_node(std::move(lights));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const glm::vec3 x(3.0f, 4.0f, 0.0f);
  const lev::SamplingPoint at{x, glm::vec3(0.0f)};
  std::vector<lev::SampledLight> enumerated;
  lev::light_probabilities(h, lev::whole_hierarchy(h, x), at, enumerated);
  ASSERT_EQ(enumerated.size(), 64u);
  double total = 0.0;
  for (const lev::SampledLight& s : enumerated) {
    ASSERT_TRUE(std::isfinite(s.probability));
    EXPECT_GT(s.probability, 0.0);
    total += s.probability;
  }
  EXPECT_NEAR(total, 1.0, 1e-9);
  EXPECT_TRUE(std::isfinite(lev::subtree_importance(h, h.root, lev::world_frame_point(x), {})));
  lev_test::OpenPoint point(x);
  lev::RandomStream random{7};
  lev::SamplingScratch scratch;
  lev::SelectionCounters counters;
  for (int draws : {1, 16}) {
    scratch.parts.clear();
    scratch.parts.subtrees.push_back(lev::whole_hierarchy(h, x));
    const glm::vec3 estimate = lev::sampled_radiance(h, draws, point, random, scratch, counters);
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(estimate[c])) << draws << " draws";
  }
}

// lev_mc at tolerance 0 culls nothing: its radiance is rt's, and its certified bound is 0 there
// (it reported +inf, 100 % of every pixel, for a render equal to rt's); above 0, where it culls
// and samples, the bound stays +inf.
TEST(LightSampling, LevMcCertifiesZeroWhereItCullsNothing) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    lev_test::Random r(seed);
    const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
    const lev::RtSelector rt(h);
    const lev::LevMcSelector exact(h, 0.0f, 1);
    const lev::LevMcSelector culling(h, 1e3f, 1);
    lev::SelectorScratch scratch;
    for (int k = 0; k < 20; ++k) {
      lev_test::OpenPoint point({r.uniform(-30, 30), r.uniform(-30, 30), r.uniform(-10, 10)});
      lev::SelectionCounters counters;
      glm::vec3 bound(-1.0f);
      const glm::vec3 radiance = exact.direct_radiance(point, scratch, counters, &bound);
      ASSERT_EQ(bound, glm::vec3(0.0f)) << "seed " << seed;
      ASSERT_EQ(radiance, rt.direct_radiance(point, scratch, counters)) << "seed " << seed;
      culling.direct_radiance(point, scratch, counters, &bound);
      ASSERT_TRUE(bound == glm::vec3(0.0f) || std::isinf(bound.x)) << "seed " << seed;
    }
  }
}

}  // namespace
