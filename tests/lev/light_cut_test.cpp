// Lightcuts' tree and cut (light_cut_tree.h, light_cut.h) on random lights: a cut holds every
// light exactly once at every relative error; at relative error 0 it is every light and its sum
// is rt's, bit for bit; a cluster's bound (light_bounds.h's radiance_bound) is at least the
// brute-force unshadowed radiance of its lights; the representatives are fixed and bright.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "lev/light_bounds.h"
#include "lev/light_cut.h"
#include "lev/light_cut_tree.h"
#include "lev/light_selector.h"
#include "tests/lev/phong_point.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::PhongPoint;
using lev_test::Random;

PhongPoint random_point(Random& r) {
  const glm::vec3 x(r.uniform(-7, 7), r.uniform(-7, 7), r.uniform(-7, 7));
  const glm::vec3 diffuse(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1));
  const float specular = r.integer(0, 1) == 0 ? 0.0f : r.uniform(0, 1);
  return PhongPoint(x, r.direction(), r.direction(), diffuse, specular, r.uniform(0.0f, 100.0f));
}

std::vector<lev::Light> random_lights(Random& r, int count) {
  std::vector<lev::Light> lights;
  for (int i = 0; i < count; ++i) lights.push_back(lev_test::random_light(r));
  return lights;
}

// Adds one to covered[i] for every light i below the node.
void cover(const lev::LightCutTree& tree, std::uint32_t node, std::vector<int>& covered) {
  const lev::CutTreeNode& n = tree.nodes[node];
  if (n.is_leaf()) {
    ++covered[n.representative];
    return;
  }
  for (const std::uint32_t child : n.children) cover(tree, child, covered);
}

TEST(LightCut, EveryCutHoldsEveryLightExactlyOnce) {
  Random r(23);
  for (int scene = 0; scene < 40; ++scene) {
    const lev::LightCutTree tree = lev::build_light_cut_tree(random_lights(r, r.integer(1, 300)));
    ASSERT_EQ(tree.nodes.size(), 2 * tree.lights.size() - 1);
    for (int p = 0; p < 10; ++p) {
      PhongPoint point = random_point(r);
      for (const float relative_error : {0.0f, 0.001f, 0.02f, 0.3f, 1.0f}) {
        for (const std::uint32_t max_size : {1u, 7u, lev::kDefaultMaxCutSize}) {
          lev::CutScratch scratch;
          lev::SelectionCounters counters;
          lev::shade_light_cut(tree, {relative_error, max_size}, point, scratch, counters);
          std::vector<int> covered(tree.lights.size(), 0);
          for (const lev::CutEntry& e : scratch.final) cover(tree, e.node, covered);
          for (std::size_t i = 0; i < covered.size(); ++i)
            ASSERT_EQ(covered[i], 1) << "light " << i;
          EXPECT_EQ(counters.lights_tested, scratch.final.size());
          if (relative_error > 0.0f) {
            EXPECT_LE(scratch.final.size(), std::max(max_size, 1u));
          }
          EXPECT_LE(counters.shadow_rays, scratch.final.size());
        }
      }
    }
  }
}

TEST(LightCut, AtRelativeErrorZeroTheCutIsEveryLightAndSumsAsRt) {
  Random r(5);
  for (int scene = 0; scene < 30; ++scene) {
    const lev::LightCutTree tree = lev::build_light_cut_tree(random_lights(r, r.integer(1, 400)));
    for (int p = 0; p < 10; ++p) {
      PhongPoint point = random_point(r);
      lev::CutScratch scratch;
      lev::SelectionCounters cut_counters;
      const glm::vec3 cut = lev::shade_light_cut(tree, {0.0f, 1u}, point, scratch,
                                                 cut_counters);  // no size limit at 0
      for (const lev::CutEntry& e : scratch.final) {
        // A cluster stays in the cut only where none of its lights can add anything.
        if (!tree.nodes[e.node].is_leaf()) {
          EXPECT_EQ(e.bound, 0.0f);
          std::vector<int> covered(tree.lights.size(), 0);
          cover(tree, e.node, covered);
          for (std::size_t i = 0; i < covered.size(); ++i) {
            if (covered[i] > 0) {
              EXPECT_EQ(point.unshadowed_radiance(tree.lights[i]), glm::vec3(0.0f));
            }
          }
        }
      }
      lev::SelectionCounters rt_counters;
      const glm::vec3 rt = lev::sum_visible_lights(
          tree.lights,
          [&](const lev::Light& l) { return lev::is_important(l, point.position(), 0.0f); }, point,
          rt_counters);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(cut[c], rt[c]) << "channel " << c;
      EXPECT_EQ(cut_counters.shadow_rays, rt_counters.shadow_rays);
    }
  }
}

TEST(LightCut, ClusterBoundIsAtLeastTheBruteForceSumOfItsLights) {
  Random r(77);
  int clusters_lit = 0;
  for (int scene = 0; scene < 30; ++scene) {
    const lev::LightCutTree tree = lev::build_light_cut_tree(random_lights(r, r.integer(2, 200)));
    for (int p = 0; p < 20; ++p) {
      const PhongPoint point = random_point(r);
      const lev::FramePoint x = lev::world_frame_point(point.position());
      for (std::uint32_t node = 0; node < tree.nodes.size(); ++node) {
        std::vector<int> covered(tree.lights.size(), 0);
        cover(tree, node, covered);
        glm::dvec3 sum(0.0);
        for (std::size_t i = 0; i < covered.size(); ++i) {
          if (covered[i] > 0) sum += glm::dvec3(point.unshadowed_radiance(tree.lights[i]));
        }
        const glm::vec3 bound =
            lev::radiance_bound(tree.nodes[node].aggregate, x, point.surface_response());
        for (int c = 0; c < 3; ++c) {
          ASSERT_GE(static_cast<double>(bound[c]), sum[c]) << "node " << node << " channel " << c;
        }
        if (sum != glm::dvec3(0.0)) ++clusters_lit;
      }
    }
  }
  EXPECT_GT(clusters_lit, 1000);  // the bound was tested where there was light to bound
}

TEST(LightCut, ResponseBoundIsZeroForABoxBehindTheSurfaceOnly) {
  lev::SurfaceResponse surface;
  surface.normal = {0.0f, 0.0f, 1.0f};
  surface.mirrored_view = {0.0f, 0.0f, 1.0f};
  surface.diffuse = glm::vec3(0.5f);
  surface.specular = 0.25f;
  surface.shininess = 10.0f;
  const lev::FramePoint x = lev::world_frame_point(glm::vec3(0.0f));
  const lev::Bounds below{{-1.0f, -1.0f, -3.0f}, {1.0f, 1.0f, -2.0f}};
  const lev::Bounds above{{-1.0f, -1.0f, 2.0f}, {1.0f, 1.0f, 3.0f}};
  EXPECT_EQ(lev::response_bound(surface, below, x), glm::vec3(0.0f));
  const glm::vec3 lit = lev::response_bound(surface, above, x);
  EXPECT_GT(lit.x, 0.5f);  // the light straight above: the full lobe and cosine
  EXPECT_LE(lit.x, 0.75f + 1e-4f);
  EXPECT_EQ(lev::largest_response(surface), glm::vec3(0.75f));
}

TEST(LightCutTree, RepresentativesAreFixedAndNeverADarkLightForALitCluster) {
  Random r(9);
  std::vector<lev::Light> lights = random_lights(r, 200);
  for (std::size_t i = 0; i < lights.size(); i += 3) lights[i].intensity = glm::vec3(0.0f);
  const lev::LightCutTree a = lev::build_light_cut_tree(lights);
  const lev::LightCutTree b = lev::build_light_cut_tree(lights);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  int representatives_seen = 0;
  std::vector<bool> represents(lights.size(), false);
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    EXPECT_EQ(a.nodes[n].representative, b.nodes[n].representative);
    const lev::CutTreeNode& node = a.nodes[n];
    if (node.aggregate.intensity != glm::vec3(0.0f)) {
      EXPECT_NE(a.lights[node.representative].intensity, glm::vec3(0.0f)) << "node " << n;
    }
    if (!node.is_leaf() && !represents[node.representative]) {
      represents[node.representative] = true;
      ++representatives_seen;
    }
  }
  // Drawn, not always the first light: many lights represent some cluster.
  EXPECT_GT(representatives_seen, 40);
}

// Random sets, degenerate ones among them (every light at one place, every light the same): each
// light is one leaf, and a second build gives the same tree, node for node.
TEST(LightCutTree, HoldsEveryLightOnceAndIsTheSameTreeEveryTime) {
  Random r(12);
  for (int set = 0; set < 60; ++set) {
    std::vector<lev::Light> lights = random_lights(r, r.integer(1, 400));
    for (lev::Light& l : lights) {
      if (set % 3 == 0) l.position = lights[0].position;
      if (set % 3 == 1) l = lights[0];
    }
    const lev::LightCutTree a = lev::build_light_cut_tree(lights);
    const lev::LightCutTree b = lev::build_light_cut_tree(lights);
    ASSERT_EQ(a.nodes.size(), 2 * lights.size() - 1) << "set " << set;
    std::vector<int> covered(lights.size(), 0);
    cover(a, 0, covered);
    for (std::size_t i = 0; i < covered.size(); ++i) ASSERT_EQ(covered[i], 1) << "light " << i;
    ASSERT_EQ(b.nodes.size(), a.nodes.size());
    for (std::size_t n = 0; n < a.nodes.size(); ++n) {
      EXPECT_EQ(a.nodes[n].children[0], b.nodes[n].children[0]) << "node " << n;
      EXPECT_EQ(a.nodes[n].children[1], b.nodes[n].children[1]) << "node " << n;
      EXPECT_EQ(a.nodes[n].representative, b.nodes[n].representative) << "node " << n;
      EXPECT_EQ(a.nodes[n].aggregate.positions.lo, b.nodes[n].aggregate.positions.lo);
      EXPECT_EQ(a.nodes[n].aggregate.positions.hi, b.nodes[n].aggregate.positions.hi);
    }
  }
}

// At every place of a grid a spot aimed up and one aimed down: the root parts them by their aim
// (a split by position alone would leave both ways on each side), so each side's cone of axes is
// a single axis and bounds something.
TEST(LightCutTree, PartsSpotsAimedOppositeWaysAtTheRoot) {
  const std::vector<lev::Light> lights = lev_test::opposite_spot_grid();
  const lev::LightCutTree tree = lev::build_light_cut_tree(lights);
  for (const std::uint32_t side : tree.nodes[0].children) {
    std::vector<int> covered(lights.size(), 0);
    cover(tree, side, covered);
    int count = 0;
    for (std::size_t i = 0; i < covered.size(); ++i) {
      if (covered[i] == 0) continue;
      ++count;
      EXPECT_EQ(lights[i].direction, tree.lights[tree.nodes[side].representative].direction);
    }
    EXPECT_EQ(count, 64);
    EXPECT_GT(tree.nodes[side].aggregate.cos_axis_spread, 0.999f);
  }
}

// Each light represents the root with probability proportional to its intensity: over many
// trees of two lights (other positions, so other draws per tree shape), the brighter one, three
// times as bright, represents the root about three quarters of the time.
TEST(LightCutTree, RepresentativeIsDrawnInProportionToIntensity) {
  int bright_won = 0, pairs = 0;
  constexpr int kTrees = 800;
  for (int t = 0; t < kTrees; ++t) {
    // The pair's node index varies with the tree's size: a row of t dim lights far to the left.
    std::vector<lev::Light> lights;
    for (int k = 0; k < t; ++k) {
      lights.push_back(
          lev::make_point_light({-1000.0f - static_cast<float>(k), 0.0f, 0.0f}, glm::vec3(1e-9f)));
    }
    lights.push_back(lev::make_point_light({0.0f, 0.0f, static_cast<float>(t)}, glm::vec3(1.0f)));
    lights.push_back(lev::make_point_light({1.0f, 0.0f, static_cast<float>(t)}, glm::vec3(3.0f)));
    const lev::LightCutTree tree = lev::build_light_cut_tree(lights);
    // The smallest cluster holding both lights of the pair.
    const auto bright = static_cast<std::uint32_t>(lights.size() - 1);
    for (const lev::CutTreeNode& n : tree.nodes) {
      if (n.is_leaf()) continue;
      if (tree.nodes[n.children[0]].is_leaf() && tree.nodes[n.children[1]].is_leaf() &&
          tree.nodes[n.children[0]].representative >= bright - 1 &&
          tree.nodes[n.children[1]].representative >= bright - 1) {
        ++pairs;
        if (n.representative == bright) ++bright_won;
      }
    }
  }
  ASSERT_EQ(pairs, kTrees);
  EXPECT_NEAR(static_cast<double>(bright_won) / kTrees, 0.75, 0.05);
}

}  // namespace
