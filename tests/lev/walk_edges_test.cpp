// The walk at the edges of the extent volumes (thesis 3.3): query points where a light's
// irradiance is within a hair of the tolerance, or within a hair of a spot's cone, seen through
// random nested rotations, scales of 2^-2 to 2^2 and translations, and lights that sit directly
// in a union (tested inline, not as frames). The walk must select exactly what the brute-force
// test selects over the lights of flatten_light_description, in the same order and with the same
// floats.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

// A unit vector at angle acos(cos_angle) from the unit axis, turned about it by a random amount.
glm::vec3 direction_at(Random& r, const glm::vec3& axis, float cos_angle) {
  glm::vec3 side = glm::cross(axis, r.direction());
  while (glm::dot(side, side) < 1e-6f) side = glm::cross(axis, r.direction());
  side = glm::normalize(side);
  const float sin_angle = std::sqrt(std::max(0.0f, 1.0f - cos_angle * cos_angle));
  return glm::normalize(cos_angle * axis + sin_angle * side);
}

// Points where the light's irradiance is the tolerance times 1 + e for small e of both signs,
// and (for spots) points just inside and just outside the cone.
std::vector<glm::vec3> points_near_the_edge(Random& r, const lev::Light& light, float tolerance) {
  std::vector<glm::vec3> points;
  const float s = lev::strength(light);
  for (float e :
       {-3e-3f, -1e-3f, -3e-4f, -1e-4f, -1e-6f, 0.0f, 1e-6f, 1e-4f, 3e-4f, 1e-3f, 3e-3f}) {
    glm::vec3 u = r.direction();
    if (light.kind == lev::LightKind::spot) {
      // Inside the cone (or anywhere, for a cone of 90 degrees or more).
      const float c = std::max(light.cos_cone_half_angle, 0.0f);
      u = direction_at(r, light.direction, c + (1.0f - c) * r.uniform(0.0f, 1.0f));
    }
    const lev::Light unit_distance = light;
    const float falloff = lev::irradiance_falloff(unit_distance, light.position + u);
    if (!(falloff > 0.0f)) continue;
    const float d = std::sqrt(s * falloff / (tolerance * (1.0f + e)));
    if (std::isfinite(d)) points.push_back(light.position + d * u);
  }
  if (light.kind == lev::LightKind::spot && light.cos_cone_half_angle > -1.0f &&
      light.cos_cone_half_angle < 1.0f) {
    for (float e : {-2e-3f, -1e-3f, -1e-5f, -1e-7f, 0.0f, 1e-7f, 1e-5f, 1e-3f, 2e-3f}) {
      const glm::vec3 u =
          direction_at(r, light.direction, std::clamp(light.cos_cone_half_angle + e, -1.0f, 1.0f));
      // Well inside the distance the tolerance allows on the axis, so the cone decides.
      const float d = 0.5f * std::sqrt(s / tolerance) * r.uniform(0.1f, 1.0f);
      if (std::isfinite(d)) points.push_back(light.position + d * u);
    }
  }
  return points;
}

void expect_walk_equals_brute_force(const lev::LightHierarchy& h, const lev::ExtentVolumes& volumes,
                                    const std::vector<lev::Light>& flat, const glm::vec3& p,
                                    float tolerance, lev::WalkScratch& scratch, std::uint64_t seed,
                                    std::size_t& kept) {
  std::vector<lev::Light> found;
  lev::WalkCounters counters;
  lev::find_important_lights(h, volumes, tolerance, p, scratch, found, counters);
  const std::vector<lev::Light> expected = lev::important_lights_brute_force(flat, p, tolerance);
  lev_test::expect_same_lights(
      found, expected, "seed " + std::to_string(seed) + " tolerance " + std::to_string(tolerance));
  kept += found.size();
}

// Builds the tree's hierarchy, fits its volumes for each tolerance and compares the walk with the
// brute force (over the tree's plain flattening) at points straddling the edge of every light's
// extent volume; counts the points and the lights kept.
void check_every_edge(const lev::LightDescription& tree, std::initializer_list<float> tolerances,
                      Random& r, std::uint64_t seed, std::size_t& points, std::size_t& kept) {
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> flat = lev::flatten_light_description(tree);
  lev::WalkScratch scratch;
  for (float tolerance : tolerances) {
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tolerance);
    for (const lev::Light& light : flat) {
      for (const glm::vec3& p : points_near_the_edge(r, light, tolerance)) {
        ++points;
        expect_walk_equals_brute_force(h, volumes, flat, p, tolerance, scratch, seed, kept);
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
  }
}

TEST(WalkEdges, MatchesTheBruteForceAtTheVolumeEdges) {
  std::size_t points = 0, kept = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    check_every_edge(tree, {1e-3f, 0.01f, 1.0f, 100.0f}, r, seed, points, kept);
    if (HasFatalFailure()) return;
  }
  // The points straddle the edges: many lights pass there and many do not.
  EXPECT_GT(points, 1000u);
  EXPECT_GT(kept, points / 4);
}

// Deeper nesting than the shared generator makes: several rotations and scales between the root
// and each light, lights of every kind, so the point reaches the light's frame through many
// inverse transforms and the light reaches the world through their composition.
TEST(WalkEdges, MatchesTheBruteForceThroughDeepNesting) {
  std::size_t points = 0, kept = 0;
  for (std::uint64_t seed = 100; seed < 160; ++seed) {
    Random r(seed);
    std::vector<lev::LightDescriptionNode> children;
    for (int i = 0; i < 12; ++i) {
      lev::LightDescriptionNode node = lev::light_node(lev_test::random_light(r));
      const int depth = r.integer(0, 3);
      for (int k = 0; k < depth; ++k)
        node = lev::affine_node(lev_test::random_similarity(r), std::move(node));
      // Some lights (untransformed ones among them) sit straight in the union, which tests them
      // without a frame of their own.
      children.push_back(r.integer(0, 1) == 0 ? lev::extent_volume_node(std::move(node))
                                              : std::move(node));
    }
    lev::LightDescription tree;
    tree.root = lev::union_node(std::move(children));
    check_every_edge(tree, {1e-2f, 3.0f}, r, seed, points, kept);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(points, 500u);
  EXPECT_GT(kept, points / 4);
}

}  // namespace
