// `lev_cut`'s walk (find_light_cut) on random instanced scenes: at relative error 0 it is
// find_important_lights' walk (the same lights, in the same order, and the same culled bound);
// above 0 the lights and representatives it returns differ from the sum over every light by at
// most its culled bound, and they are fewer than the lights at many points. The selector at
// relative error 0 gives rt's radiance bit for bit. A cluster lit by a centred representative
// casts its shadow ray to one of its own lights, a different one in each instance of a master.
// A small cluster of spots aimed apart is shaded from its own lights: its estimate is their sum,
// its ray goes to one of them drawn in proportion to its radiance at the point.
// The table of the nodes the cut reads per cluster names the lights a walk down would find. The
// unshadowed radiance the walk keeps for the shading is that of each light it returns.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/hierarchy_cursor.h"
#include "lev/important_lights.h"
#include "lev/inspect_record.h"
#include "lev/light_bvh.h"
#include "lev/light_cut_tree.h"
#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "lev/selector_lev_cut.h"
#include "lev/selector_rt.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

// A surface that faces every light, reflects irradiance unchanged and is never shadowed, and
// says so (a response of 1 from every direction), so a cluster's radiance bound is its
// irradiance bound and the direct radiance is the summed irradiance of what a method returns.
class UnitResponsePoint : public lev::ShadingPoint {
 public:
  explicit UnitResponsePoint(const glm::vec3& x) : x_(x) {}
  glm::vec3 position() const override { return x_; }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    return lev::irradiance(light, x_);
  }
  bool visible(const lev::Light&) override { return true; }
  lev::SurfaceResponse surface_response() const override {
    lev::SurfaceResponse unit;
    unit.diffuse = glm::vec3(1.0f);
    return unit;
  }

 private:
  glm::vec3 x_;
};

glm::dvec3 summed_irradiance(const std::vector<lev::Light>& lights, const glm::vec3& x) {
  glm::dvec3 sum(0.0);
  for (const lev::Light& l : lights) sum += glm::dvec3(lev::irradiance(l, x));
  return sum;
}

// A description with what the cut's tests read of it: its hierarchy, its lights in world space
// (flattened without the walk) and the cut's node table.
struct CutScene {
  explicit CutScene(const lev::LightDescription& tree)
      : h(lev::build_hierarchy(tree)),
        world_lights(lev::flatten_light_description(tree)),
        table(lev::make_cut_node_table(h)) {}
  lev::LightHierarchy h;
  std::vector<lev::Light> world_lights;
  lev::CutNodeTable table;
};

TEST(LevCut, RelativeErrorZeroIsLevsWalk) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Random r(seed);
    const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
    const lev::CutNodeTable table = lev::make_cut_node_table(h);
    lev::WalkScratch scratch;
    for (const float tau : {0.0f, 1e-3f, 1e-2f, 1.0f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      for (int k = 0; k < 30; ++k) {
        const glm::vec3 x(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
        const std::string context = "seed " + std::to_string(seed) + " tau " + std::to_string(tau) +
                                    " k " + std::to_string(k);
        UnitResponsePoint point(x);
        std::vector<lev::Light> plain, cut;
        lev::WalkCounters plain_counters, cut_counters;
        glm::vec3 plain_bound(-1.0f), cut_bound(-2.0f);
        lev::find_important_lights(h, volumes, tau, x, scratch, plain, plain_counters,
                                   &plain_bound);
        lev::find_light_cut(h, volumes, table, tau, 0.0f, point, scratch, cut, cut_counters,
                            &cut_bound);
        lev_test::expect_same_lights(cut, plain, context);
        ASSERT_EQ(cut_bound, plain_bound) << context;
        ASSERT_EQ(cut_counters.nodes_visited, plain_counters.nodes_visited) << context;
      }
    }
  }
}

TEST(LevCut, ErrorWithinTheCulledBoundAndClustersFormed) {
  std::uint64_t clustered_points = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Random r(seed);
    const CutScene scene(lev_test::random_instanced_tree(r));
    const lev::LightHierarchy& h = scene.h;
    const std::vector<lev::Light>& world_lights = scene.world_lights;
    const lev::CutNodeTable& table = scene.table;
    lev::WalkScratch scratch;
    for (const float tau : {0.0f, 1e-3f, 1e-1f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tau);
      for (const float relative_error : {1e-3f, 0.02f, 0.3f, 1.0f}) {
        for (int k = 0; k < 30; ++k) {
          const glm::vec3 x(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
          const std::string context = "seed " + std::to_string(seed) + " tau " +
                                      std::to_string(tau) + " relative error " +
                                      std::to_string(relative_error) + " k " + std::to_string(k);
          UnitResponsePoint point(x);
          std::vector<lev::Light> cut;
          lev::WalkCounters counters;
          glm::vec3 bound(-1.0f);
          lev::find_light_cut(h, volumes, table, tau, relative_error, point, scratch, cut, counters,
                              &bound);
          // The estimates the walk keeps for the shading are those of the lights it returns, in
          // their order, bit for bit (the shading uses them instead of computing them again).
          // An exact cluster's estimate is its lights' sum instead (ExactClustersAreShadedFrom...).
          ASSERT_EQ(scratch.cut_estimates.size(), cut.size()) << context;
          const std::vector<std::size_t>& exact_clusters = scratch.exact_clusters;
          glm::dvec3 estimate(0.0);
          for (std::size_t i = 0; i < cut.size(); ++i) {
            estimate += glm::dvec3(scratch.cut_estimates[i]);
            if (std::find(exact_clusters.begin(), exact_clusters.end(), i) != exact_clusters.end())
              continue;
            ASSERT_EQ(scratch.cut_estimates[i], point.unshadowed_radiance(cut[i])) << context;
          }
          const glm::dvec3 exact = summed_irradiance(world_lights, x);
          for (int c = 0; c < 3; ++c) {
            // The bound is rounded up once; the sums differ in order by float roundings.
            ASSERT_LE(std::abs(estimate[c] - exact[c]),
                      static_cast<double>(bound[c]) * (1.0 + 1e-4) + 1e-6 * exact[c])
                << context << ", channel " << c;
          }
          if (cut.size() < world_lights.size() && bound != glm::vec3(0.0f)) ++clustered_points;
        }
      }
    }
  }
  EXPECT_GT(clustered_points, 1000u);
}

TEST(LevCut, SelectorAtRelativeErrorZeroIsRt) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Random r(seed);
    const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
    const lev::RtSelector rt(h);
    const lev::LevCutSelector cut(h, 0.0f);
    for (int k = 0; k < 30; ++k) {
      UnitResponsePoint point({r.uniform(-30, 30), r.uniform(-30, 30), r.uniform(-10, 10)});
      lev::SelectorScratch scratch;
      lev::SelectionCounters counters;
      const glm::vec3 exact = rt.direct_radiance(point, scratch, counters);
      ASSERT_EQ(cut.direct_radiance(point, scratch, counters), exact) << "seed " << seed;
    }
  }
}

// Dark lights (intensity 0) grouped in a union of their own, alone and beside a bright light:
// the node table draws a light from every union in proportion to intensity, and a union whose
// lights were all dark drew the root again and again (`levrt render --method lev_cut` of a scene
// of 30 dark lights hung while setting up the method). The selector is made, and it is rt's.
TEST(LevCut, UnionsOfDarkLightsAreDrawnFromAndTheSelectorIsRt) {
  for (bool beside_a_bright_light : {false, true}) {
    std::vector<lev::LightDescriptionNode> dark;
    for (int k = 0; k < 30; ++k) {
      const glm::vec3 at(0.1f * static_cast<float>(k % 3), 0.0f, 3.0f);
      dark.push_back(lev::light_node(lev::make_point_light(at, glm::vec3(0.0f))));
    }
    std::vector<lev::LightDescriptionNode> root;
    root.push_back(lev::union_node(std::move(dark)));
    if (beside_a_bright_light)
      root.push_back(lev::light_node(lev::make_point_light({2, 0, 3}, glm::vec3(1.0f))));
    lev::LightDescription tree;
    tree.root = lev::union_node(std::move(root));
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const lev::RtSelector rt(h);
    for (float relative_error : {0.0f, 0.02f, 1.0f}) {
      const lev::LevCutSelector cut(h, relative_error);
      for (const glm::vec3& x : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 3), glm::vec3(5, 5, 1)}) {
        UnitResponsePoint point(x);
        lev::SelectorScratch scratch;
        lev::SelectionCounters counters;
        EXPECT_EQ(cut.direct_radiance(point, scratch, counters),
                  rt.direct_radiance(point, scratch, counters))
            << "relative error " << relative_error << (beside_a_bright_light ? ", bright" : "");
      }
    }
  }
}

// Sees exactly the positions of the scene's lights (within float rounding of the walk's
// arithmetic) and nothing else, as a point whose view is blocked everywhere but toward the lights
// themselves; counts its shadow rays. Faces every light with a unit response.
class SeesOnlyTheLights final : public lev::ShadingPoint {
 public:
  SeesOnlyTheLights(const glm::vec3& x, const std::vector<lev::Light>& lights)
      : x_(x), lights_(lights) {}
  glm::vec3 position() const override { return x_; }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    return lev::irradiance(light, x_);
  }
  bool visible(const lev::Light& target) override {
    ++rays;
    for (const lev::Light& l : lights_) {
      if (glm::length(l.position - target.position) <= 1e-4f * (1.0f + lev::max_abs(l.position)))
        return true;
    }
    return false;
  }
  lev::SurfaceResponse surface_response() const override {
    lev::SurfaceResponse unit;
    unit.diffuse = glm::vec3(1.0f);
    return unit;
  }
  int rays = 0;

 private:
  glm::vec3 x_;
  const std::vector<lev::Light>& lights_;
};

// A master of four point lights (a fixture split in four) placed at 64 places of a grid by
// translations, as the hall's rig is made.
lev::LightDescription rig_of_fixtures() {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> quarters;
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 at(0.3f * static_cast<float>(k % 2), 0.3f * static_cast<float>(k / 2), 0.0f);
    quarters.push_back(lev::light_node(lev::make_point_light(at, glm::vec3(1.0f))));
  }
  tree.masters.push_back(lev::union_node(std::move(quarters)));
  std::vector<lev::LightDescriptionNode> fixtures;
  for (int k = 0; k < 64; ++k) {
    const glm::vec3 at(2.0f * static_cast<float>(k % 8), 2.0f * static_cast<float>(k / 8), 10.0f);
    fixtures.push_back(lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  tree.root = lev::union_node(std::move(fixtures));
  return tree;
}

TEST(LevCut, ACentredClusterCastsItsRayToOneOfItsLights) {
  // Every light is seen and the centres of the clusters' boxes are not: the cut's radiance is
  // then its unshadowed estimate, every cluster counted, as where the lights are all seen.
  std::uint64_t centred_clusters = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Random r(seed);
    const lev::LightDescription tree =
        seed == 1 ? rig_of_fixtures() : lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    for (const float relative_error : {0.02f, 0.3f}) {
      const lev::LevCutSelector cut(h, relative_error);
      for (int k = 0; k < 30; ++k) {
        const glm::vec3 x(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
        const std::string context = "seed " + std::to_string(seed) + " relative error " +
                                    std::to_string(relative_error) + " k " + std::to_string(k);
        SeesOnlyTheLights point(x, world_lights);
        lev::SelectorScratch scratch;
        lev::SelectionCounters counters;
        const glm::vec3 radiance = cut.direct_radiance(point, scratch, counters);
        // Every entry's estimate (an exact cluster's is its lights' sum, not its drawn light's)
        // counts: each ray went to a light.
        ASSERT_EQ(scratch.walk.cut_estimates.size(), scratch.lights.size()) << context;
        glm::dvec3 unshadowed(0.0);
        for (const glm::vec3& estimate : scratch.walk.cut_estimates)
          unshadowed += glm::dvec3(estimate);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(radiance[c], unshadowed[c], 1e-5 * (1.0 + unshadowed[c])) << context;
        ASSERT_EQ(static_cast<std::uint64_t>(point.rays), counters.shadow_rays) << context;
        centred_clusters += scratch.walk.centred_clusters.size();
      }
    }
  }
  EXPECT_GT(centred_clusters, 100u);
}

TEST(LevCut, TheInstancesOfAMasterCastTheirRaysToDifferentLights) {
  // Below the rig, its fixtures are clusters, instances of one master: the light each one's ray
  // goes to, taken relative to its fixture (on a grid of 2), is not the same in every fixture.
  const lev::LightHierarchy h = lev::build_hierarchy(rig_of_fixtures());
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, 0.0f);
  const lev::CutNodeTable table = lev::make_cut_node_table(h);
  UnitResponsePoint point({7.0f, 7.0f, -20.0f});
  lev::WalkScratch scratch;
  std::vector<lev::Light> lights;
  lev::WalkCounters counters;
  lev::find_light_cut(h, volumes, table, 0.0f, 0.02f, point, scratch, lights, counters);
  // The clusters that are one fixture each: four unit lights.
  std::vector<const lev::CutCluster*> fixtures;
  for (const lev::CutCluster& cluster : scratch.centred_clusters) {
    const std::uint32_t below = lev::pass_transforms(h, cluster.node);
    if (lev::kept_aggregate(h, below).intensity.x == 4.0f) fixtures.push_back(&cluster);
  }
  ASSERT_GE(fixtures.size(), 8u);
  std::vector<glm::vec3> within_fixture;
  for (const lev::CutCluster* cluster : fixtures) {
    const glm::vec3 target = lev::cluster_shadow_target(h, table, *cluster).position;
    const glm::vec3 at = target - 2.0f * glm::floor(0.5f * target);
    if (std::find(within_fixture.begin(), within_fixture.end(), at) == within_fixture.end())
      within_fixture.push_back(at);
  }
  EXPECT_GT(within_fixture.size(), 1u);
}

// A light of a subtree in the lights' order, with what lies on its way down from the subtree.
struct LightBelow {
  std::uint32_t node = 0;
  double scale2 = 1.0;           // the product of the transforms' scales, squared
  bool transformed = false;      // some transform lies on the way
  bool not_translation = false;  // some transform that is not a pure translation does
};

void collect_lights_below(const lev::LightHierarchy& h, std::uint32_t node, LightBelow way,
                          std::vector<LightBelow>& out) {
  const lev::HierarchyNode& n = h.nodes[node];
  switch (lev::node_role(n)) {
    case lev::NodeRole::light:
      way.node = node;
      out.push_back(way);
      return;
    case lev::NodeRole::group:
      for (const std::uint32_t child : lev::group_children(h, n))
        collect_lights_below(h, child, way, out);
      return;
    case lev::NodeRole::transform: {
      const double s = lev::node_transform(h, n).scale;
      way.scale2 *= s * s;
      way.transformed = true;
      way.not_translation = way.not_translation || !lev::is_translation_only(n);
      break;
    }
    case lev::NodeRole::bounded:
    case lev::NodeRole::reference:
      break;
  }
  collect_lights_below(h, lev::only_child(n, node), way, out);
}

// Nested unions of bare lights and of lights below pure translations: what the cut's table
// remembers per node instead of walking down per cluster.
lev::LightDescription translated_union_tree(Random& r) {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> groups;
  for (int g = 0; g < 6; ++g) {
    std::vector<lev::LightDescriptionNode> lights;
    for (int k = r.integer(1, 5); k > 0; --k) {
      lev::LightDescriptionNode light = lev::light_node(lev_test::random_light(r));
      if (r.integer(0, 2) == 0) {
        light = lev::affine_node(
            lev::make_translation({r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5)}),
            std::move(light));
      }
      lights.push_back(std::move(light));
    }
    groups.push_back(lev::union_node(std::move(lights)));
  }
  tree.root = lev::union_node(std::move(groups));
  return tree;
}

// Per node, the table holds the summed intensity a draw weighs the subtree by, and a light it
// names is the one the walk down would find: for an unshifted draw a light of the subtree with
// weight and no transform on its way, for the centred representative the subtree's first light
// with only translations on its way; each is named whenever that condition holds. Its light
// count is the number of lights below it.
TEST(LevCut, TheNodeTableNamesTheLightsTheWalkDownFinds) {
  std::uint64_t drawn_named = 0, first_named = 0, translated_first_named = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Random r(seed);
    for (const lev::LightDescription& tree :
         {lev_test::random_instanced_tree(r), translated_union_tree(r)}) {
      const lev::LightHierarchy h = lev::build_hierarchy(tree);
      const lev::CutNodeTable table = lev::make_cut_node_table(h);
      ASSERT_EQ(table.draw_weights.size(), h.nodes.size());
      ASSERT_EQ(table.drawn_lights.size(), h.nodes.size());
      ASSERT_EQ(table.first_lights.size(), h.nodes.size());
      ASSERT_EQ(table.light_counts.size(), h.nodes.size());
      for (std::uint32_t node = 0; node < h.nodes.size(); ++node) {
        const std::string context =
            "seed " + std::to_string(seed) + " node " + std::to_string(node);
        std::vector<LightBelow> below;
        collect_lights_below(h, node, LightBelow{}, below);
        double weight = 0.0;
        for (const LightBelow& l : below)
          weight += l.scale2 * lev::draw_weight(lev::leaf_light(h, h.nodes[l.node]).intensity);
        // Summed from the aggregates, which round their sums up.
        ASSERT_GE(table.draw_weights[node], weight * (1.0 - 1e-6)) << context;
        ASSERT_LE(table.draw_weights[node], weight * (1.0 + 1e-4) + 1e-30) << context;
        ASSERT_EQ(table.light_counts[node], below.size()) << context;
        const lev::NodeRole role = lev::node_role(h.nodes[node]);
        if (below.empty() || role == lev::NodeRole::light || role == lev::NodeRole::transform) {
          ASSERT_EQ(table.drawn_lights[node], ~0u) << context;
          ASSERT_EQ(table.first_lights[node], ~0u) << context;
          continue;
        }
        const bool none_transformed = std::none_of(
            below.begin(), below.end(), [](const LightBelow& l) { return l.transformed; });
        if (table.drawn_lights[node] != ~0u) {
          const auto drawn = std::find_if(below.begin(), below.end(), [&](const LightBelow& l) {
            return l.node == table.drawn_lights[node];
          });
          ASSERT_NE(drawn, below.end()) << context;
          EXPECT_FALSE(drawn->transformed) << context;
          EXPECT_GT(lev::draw_weight(lev::leaf_light(h, h.nodes[drawn->node]).intensity), 0.0)
              << context;
          ++drawn_named;
        } else if (none_transformed && weight > 0.0) {
          ADD_FAILURE() << context << ": no transform below, yet no light named for the draw";
        }
        if (below.front().not_translation) {
          EXPECT_EQ(table.first_lights[node], ~0u) << context;
        } else {
          ASSERT_EQ(table.first_lights[node], below.front().node) << context;
          ++first_named;
          if (below.front().transformed) ++translated_first_named;
        }
      }
    }
  }
  EXPECT_GT(drawn_named, 100u);
  EXPECT_GT(translated_first_named, 10u);
  EXPECT_GT(first_named, translated_first_named);
}

// Five fixtures of six coloured spots, each spot tilted 50 degrees from straight down and the six
// turned apart (a stage rig's fixture aims its spots apart): 30 lights, so every cluster the cut
// makes holds at most 30 and is one a drawn representative would stand for, an exact cluster.
lev::LightDescription fixtures_of_spots_aimed_apart() {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> spots;
  for (int k = 0; k < 6; ++k) {
    const float azimuth = 1.0471976f * static_cast<float>(k);
    const glm::vec3 aim(0.766f * std::cos(azimuth), 0.766f * std::sin(azimuth), -0.643f);
    const glm::vec3 colour(0.2f + 0.8f * static_cast<float>(k % 2),
                           0.2f + 0.4f * static_cast<float>(k % 3), 1.0f - 0.15f * k);
    spots.push_back(lev::light_node(
        lev::make_spot_light(glm::vec3(0.2f * std::cos(azimuth), 0.2f * std::sin(azimuth), 0.0f),
                             aim, 40.0f * colour, 0.6f, 2.0f)));
  }
  tree.masters.push_back(lev::union_node(std::move(spots)));
  std::vector<lev::LightDescriptionNode> fixtures;
  for (int k = 0; k < 5; ++k) {
    const glm::vec3 at(3.0f * static_cast<float>(k) - 6.0f, 0.5f * static_cast<float>(k), 8.0f);
    fixtures.push_back(lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  tree.root = lev::union_node(std::move(fixtures));
  return tree;
}

// Index lists of the walk: strictly increasing, each below `size`.
bool increasing_below(const std::vector<std::size_t>& indices, std::size_t size) {
  for (std::size_t k = 0; k < indices.size(); ++k) {
    if (indices[k] >= size || (k > 0 && indices[k] <= indices[k - 1])) return false;
  }
  return true;
}

// What check_refined_cuts saw: points whose refined cut grew, and exact clusters in refined cuts.
struct RefinedCuts {
  std::uint64_t finer = 0;
  std::uint64_t exact_clusters = 0;
};

// A cut at x, then two cuts made finer by going on from the last one (refine_light_cut), each
// halving the relative error, checked as a cut: its lists are parallel to its lights, its running
// total is the sum of its estimates, its error against the sum over every light is within its
// bound.
void check_refined_cuts(const CutScene& scene, const lev::ExtentVolumes& volumes, float tau,
                        float relative_error, const glm::vec3& x, lev::WalkScratch& scratch,
                        const std::string& where, RefinedCuts& seen) {
  const lev::LightHierarchy& h = scene.h;
  const lev::CutNodeTable& table = scene.table;
  const std::vector<lev::Light>& world_lights = scene.world_lights;
  UnitResponsePoint point(x);
  const glm::dvec3 exact = summed_irradiance(world_lights, x);
  std::vector<lev::Light> cut;
  lev::WalkCounters counters;
  std::size_t last_size = 0;
  float e = relative_error;
  for (int round = 0; round < 3; ++round) {
    SCOPED_TRACE(where + " relative error " + std::to_string(e));
    const bool may_refine = round < 2;
    if (round == 0) {
      lev::start_light_cut(h, volumes, table, tau, e, point, scratch, cut, counters, may_refine,
                           false, 1.0f);
    } else {
      lev::refine_light_cut(h, volumes, table, tau, e, point, scratch, cut, counters, may_refine);
      seen.exact_clusters += scratch.exact_clusters.size();
    }
    ASSERT_EQ(scratch.cut_estimates.size(), cut.size());
    ASSERT_TRUE(increasing_below(scratch.exact_clusters, cut.size()));
    ASSERT_TRUE(increasing_below(scratch.several_light_clusters, cut.size()));
    std::vector<std::size_t> centred;
    for (const lev::CutCluster& c : scratch.centred_clusters) {
      ASSERT_NE(table.centred[c.node], 0);
      centred.push_back(c.index);
    }
    ASSERT_TRUE(increasing_below(centred, cut.size()));
    if (may_refine) {  // one record per cluster, in the order of their lights
      std::vector<std::size_t> kept;
      for (const lev::CutSubtree& c : scratch.kept_clusters) {
        kept.push_back(c.kept_as);
        ASSERT_EQ(c.centred, std::binary_search(centred.begin(), centred.end(), c.kept_as));
      }
      ASSERT_TRUE(increasing_below(kept, cut.size()));
      for (const std::size_t i : centred)
        ASSERT_TRUE(std::binary_search(kept.begin(), kept.end(), i));
      for (const std::size_t i : scratch.exact_clusters)
        ASSERT_TRUE(std::binary_search(kept.begin(), kept.end(), i));
    }
    glm::dvec3 estimate(0.0);
    for (std::size_t i = 0; i < cut.size(); ++i) {
      estimate += glm::dvec3(scratch.cut_estimates[i]);
      if (std::binary_search(scratch.exact_clusters.begin(), scratch.exact_clusters.end(), i))
        continue;
      ASSERT_EQ(scratch.cut_estimates[i], point.unshadowed_radiance(cut[i])) << i;
    }
    glm::vec3 bound(-1.0f);
    lev::answer_light_cut_bounds(h, tau, scratch, &bound);
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(scratch.cut_sums.total[c], estimate[c], 1e-4 * (1.0 + estimate[c])) << c;
      ASSERT_LE(std::abs(estimate[c] - exact[c]),
                static_cast<double>(bound[c]) * (1.0 + 1e-4) + 1e-6 * exact[c])
          << c;
    }
    if (round > 0 && cut.size() > last_size) ++seen.finer;
    last_size = cut.size();
    e *= 0.5f;
  }
}

// Cuts made finer by going on from the last one are cuts (check_refined_cuts), on random
// instanced scenes and on fixtures of spots aimed apart (exact clusters kept again), and finer
// at many points (a cluster opened may also leave nothing: its parts dark or dropped by the
// volumes).
TEST(LevCut, ARefinedCutGoesOnFromTheLastOne) {
  RefinedCuts seen;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Random r(seed);
    const CutScene scene(lev_test::random_instanced_tree(r));
    lev::WalkScratch scratch;
    for (const float tau : {0.0f, 1e-2f}) {
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.h, tau);
      for (const float relative_error : {0.02f, 0.3f, 1.0f}) {
        for (int k = 0; k < 25; ++k) {
          const glm::vec3 x(r.uniform(-40, 40), r.uniform(-40, 40), r.uniform(-10, 10));
          check_refined_cuts(scene, volumes, tau, relative_error, x, scratch,
                             "seed " + std::to_string(seed) + " k " + std::to_string(k), seen);
          if (HasFatalFailure()) return;
        }
      }
    }
  }
  EXPECT_GT(seen.finer, 200u);
  const CutScene fixtures(fixtures_of_spots_aimed_apart());
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(fixtures.h, 0.0f);
  lev::WalkScratch scratch;
  Random r(11);
  const RefinedCuts random_scenes = seen;
  for (int k = 0; k < 100; ++k) {
    const glm::vec3 x(r.uniform(-12, 12), r.uniform(-6, 6), r.uniform(-2, 2));
    check_refined_cuts(fixtures, volumes, 0.0f, 1.0f, x, scratch, "fixtures k " + std::to_string(k),
                       seen);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(seen.exact_clusters - random_scenes.exact_clusters, 30u);
}

// A panel of 10,000 dim lights (a flat list: the automatic hierarchy), each below the tolerance
// lev_cut's volumes drop at, that together light the points below it: the drop is held within the
// relative error of the total, so the panel is cut (its clusters shaded) rather than dropped
// whole (it was: no light tested, the radiance 0). Where the panel lights a point little (far
// off to the side), the drop stays within its floor.
TEST(LevCut, ManyLightsEachBelowTheToleranceAreCutNotDropped) {
  std::vector<lev::Light> panel;
  for (int k = 0; k < 10000; ++k) {
    const glm::vec3 at(0.1f * static_cast<float>(k % 100) - 5.0f,
                       0.1f * static_cast<float>(k / 100) - 5.0f, 3.0f);
    panel.push_back(lev::make_point_light(at, glm::vec3(2e-4f)));
  }
  lev::LightDescription tree;
  tree.root = lev::build_light_bvh(panel);
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const float relative_error = 0.02f;
  const lev::LevCutSelector selector(h, relative_error);
  Random r(5);
  for (int k = 0; k < 30; ++k) {
    const glm::vec3 x(r.uniform(-4, 4), r.uniform(-4, 4), 0.0f);
    UnitResponsePoint point(x);
    const double truth = summed_irradiance(panel, x).x;
    // Each light is below the drop's tolerance (irradiance, at exposure 1) at every such point.
    ASSERT_LT(2e-4 / 9.0, relative_error * lev::kDropToleranceOfRelativeError);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const glm::vec3 radiance = selector.direct_radiance(point, scratch, counters);
    EXPECT_GT(counters.lights_tested, 0u) << k;
    EXPECT_NEAR(radiance.x, truth, 2.0 * relative_error * truth) << k;
  }
  // Far to the side the panel adds little: the drop, within its floor, is left as it is.
  for (int k = 0; k < 10; ++k) {
    const glm::vec3 x(400.0f + 10.0f * static_cast<float>(k), 0.0f, 0.0f);
    UnitResponsePoint point(x);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const glm::vec3 radiance = selector.direct_radiance(point, scratch, counters);
    EXPECT_EQ(counters.lights_tested, 0u) << k;
    EXPECT_LE(summed_irradiance(panel, x).x - radiance.x, relative_error * lev::kTotalFloorOfWhite)
        << k;
  }
}

// A ceiling of 4,096 spots aimed down over the half-space below (160 m square, as the car park's),
// and points 5 cm above it, which no spot reaches while the bounds of its parts, boxes of cones
// opening at the horizontal seen from nearly level, do not say so. At exposure 8 EV the volumes
// drop little (the tolerance scales with white), and judged against the total, about 0, every
// part was opened down to its lights (9,208 nodes per point). Judged against at least
// kTotalFloorOfWhite of white, the cut visits a few nodes per point, and errs by at most the
// relative error of that floor per entry of the cut.
TEST(LevCut, AtAPointNoLightReachesTheCutIsJudgedAgainstTheFloor) {
  std::vector<lev::Light> ceiling;
  std::vector<lev::BvhItem> placed;
  const lev::Light spot = lev::make_spot_light(glm::vec3(0.0f), {0.0f, 0.0f, -1.0f},
                                               glm::vec3(0.05f), 1.5707964f, 1.0f);
  for (int k = 0; k < 4096; ++k) {
    const glm::vec3 at(2.5f * static_cast<float>(k % 64), 2.5f * static_cast<float>(k / 64), 3.0f);
    lev::Light moved = spot;
    moved.position = at;
    ceiling.push_back(moved);
    lev::LightDescriptionNode node =
        lev::affine_node(lev::make_translation(at), lev::light_node(spot));
    const lev::SubtreeLights lights = lev::subtree_lights(node, {});
    placed.push_back({std::move(node), lights});
  }
  lev::LightDescription tree;
  tree.root = lev::build_bvh(std::move(placed));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const float relative_error = 0.02f;
  const float exposure = 256.0f;
  const lev::LevCutSelector selector(h, relative_error, exposure);
  std::uint64_t nodes = 0;
  Random r(11);
  const int points = 20;
  for (int k = 0; k < points; ++k) {
    const glm::vec3 x(r.uniform(0, 160), r.uniform(0, 160), 3.05f);
    ASSERT_EQ(summed_irradiance(ceiling, x).x, 0.0) << k;
    UnitResponsePoint point(x);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const glm::vec3 radiance = selector.direct_radiance(point, scratch, counters);
    nodes += counters.nodes_visited;
    EXPECT_LE(radiance.x, static_cast<float>(counters.lights_tested) * relative_error *
                              lev::kTotalFloorOfWhite / exposure)
        << k;
  }
  EXPECT_LT(nodes, static_cast<std::uint64_t>(points) * 100u);
}

// Every light is seen; each shadow ray's target is kept.
class RecordsItsRays final : public UnitResponsePoint {
 public:
  using UnitResponsePoint::UnitResponsePoint;
  bool visible(const lev::Light& target) override {
    targets.push_back(target);
    return true;
  }
  std::vector<lev::Light> targets;
};

TEST(LevCut, ExactClustersAreShadedFromTheirOwnLights) {
  // Spots aimed apart: a representative's unshadowed radiance is far from its cluster's (one whose
  // cone misses the point stands for others that light it), so these clusters are shaded from
  // their own lights. Every cluster here is exact, so with every light seen the cut's estimate is
  // the sum over every light, and each cluster's ray goes to one of its lights that lights the
  // point.
  const lev::LightDescription tree = fixtures_of_spots_aimed_apart();
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, 0.0f);
  const lev::CutNodeTable table = lev::make_cut_node_table(h);
  Random r(7);
  lev::WalkScratch scratch;
  std::uint64_t exact_clusters = 0;
  for (const float relative_error : {0.05f, 0.3f, 1.0f}) {
    for (int k = 0; k < 200; ++k) {
      const glm::vec3 x(r.uniform(-12, 12), r.uniform(-6, 6), r.uniform(-2, 2));
      const std::string context =
          "relative error " + std::to_string(relative_error) + " k " + std::to_string(k);
      RecordsItsRays point(x);
      std::vector<lev::Light> cut;
      lev::WalkCounters counters;
      lev::find_light_cut(h, volumes, table, 0.0f, relative_error, point, scratch, cut, counters);
      glm::dvec3 estimate(0.0);
      for (const glm::vec3& e : scratch.cut_estimates) estimate += glm::dvec3(e);
      const glm::dvec3 exact = summed_irradiance(world_lights, x);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(estimate[c], exact[c], 1e-5 * exact[c] + 1e-9) << context << ", channel " << c;
      EXPECT_TRUE(scratch.centred_clusters.empty()) << context;
      for (const std::size_t i : scratch.exact_clusters) {
        ASSERT_LT(i, cut.size()) << context;
        EXPECT_GT(lev::brightest(point.unshadowed_radiance(cut[i])), 0.0f) << context;
        const bool a_light_of_the_scene =
            std::any_of(world_lights.begin(), world_lights.end(), [&](const lev::Light& l) {
              return glm::length(l.position - cut[i].position) < 1e-5f &&
                     l.intensity == cut[i].intensity;
            });
        EXPECT_TRUE(a_light_of_the_scene) << context << ", cluster light " << i;
      }
      exact_clusters += scratch.exact_clusters.size();
      // Their lights are counted as work (the rt fallback's probe weighs them), at most once each.
      if (scratch.exact_clusters.empty()) {
        EXPECT_EQ(counters.lights_evaluated, 0u) << context;
      } else {
        EXPECT_GE(counters.lights_evaluated, scratch.exact_clusters.size()) << context;
        EXPECT_LE(counters.lights_evaluated, world_lights.size()) << context;
      }
      // The same point gives the same cut: the draw depends on the point alone.
      std::vector<lev::Light> again;
      lev::find_light_cut(h, volumes, table, 0.0f, relative_error, point, scratch, again, counters);
      ASSERT_EQ(again.size(), cut.size()) << context;
      for (std::size_t i = 0; i < cut.size(); ++i)
        ASSERT_EQ(again[i].position, cut[i].position) << context;
    }
  }
  EXPECT_GT(exact_clusters, 300u);
}

TEST(LevCut, AnExactClustersRayGoesToALightDrawnInProportionToItsRadiance) {
  // Two spots at one place, aimed 45 degrees apart to either side of straight down, both lighting
  // every point below (cones of 80 degrees, no dropoff): red 1 and green 3, so at each point the
  // green one gives three times the red one's radiance and should take three rays in four.
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> pair;
  pair.push_back(lev::light_node(lev::make_spot_light(
      {0.0f, 0.0f, 10.0f}, {0.7071f, 0.0f, -0.7071f}, {1.0f, 0.0f, 0.0f}, 1.396f, 0.0f)));
  pair.push_back(lev::light_node(lev::make_spot_light(
      {0.0f, 0.0f, 10.0f}, {-0.7071f, 0.0f, -0.7071f}, {0.0f, 3.0f, 0.0f}, 1.396f, 0.0f)));
  std::vector<lev::LightDescriptionNode> root;
  root.push_back(lev::union_node(std::move(pair)));
  root.push_back(lev::light_node(lev::make_point_light({50.0f, 50.0f, 50.0f}, glm::vec3(1.0f))));
  tree.root = lev::union_node(std::move(root));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, 0.0f);
  const lev::CutNodeTable table = lev::make_cut_node_table(h);
  Random r(11);
  lev::WalkScratch scratch;
  int draws = 0, green = 0;
  for (int k = 0; k < 4000; ++k) {
    RecordsItsRays point({r.uniform(-1, 1), r.uniform(-1, 1), 0.0f});
    std::vector<lev::Light> cut;
    lev::WalkCounters counters;
    lev::find_light_cut(h, volumes, table, 0.0f, 1.0f, point, scratch, cut, counters);
    for (const std::size_t i : scratch.exact_clusters) {
      ++draws;
      if (cut[i].intensity.y > 0.0f) ++green;
    }
  }
  ASSERT_GT(draws, 3000);
  const double share = static_cast<double>(green) / draws;
  EXPECT_NEAR(share, 0.75, 0.03) << green << " of " << draws;
}

// Faces every light with a unit response, and a wall hides every light on the near side of the
// plane x = wall_x; counts the shadow rays it is asked for.
class BehindAWall final : public UnitResponsePoint {
 public:
  BehindAWall(const glm::vec3& x, float wall_x) : UnitResponsePoint(x), wall_x_(wall_x) {}
  bool visible(const lev::Light& target) override {
    ++rays;
    if (std::find(asked.begin(), asked.end(), target.position) != asked.end()) ++asked_again;
    asked.push_back(target.position);
    return target.position.x > wall_x_;
  }
  // The summed irradiance of the lights the wall leaves seen (brightest channel: x).
  double truth(const std::vector<lev::Light>& lights) const {
    double sum = 0.0;
    for (const lev::Light& l : lights) {
      if (l.position.x > wall_x_) sum += lev::irradiance(l, position()).x;
    }
    return sum;
  }
  int rays = 0;
  int asked_again = 0;  // rays to a position asked already at this point
  std::vector<glm::vec3> asked;

 private:
  float wall_x_;
};

// The noise check against none, summed over the points compared: the errors against the lights
// the wall leaves seen, the lights tested and the rays cast.
struct CheckAgainstNone {
  double checked_error = 0.0, unchecked_error = 0.0;
  std::uint64_t checked_tested = 0, unchecked_tested = 0, checked_rays = 0, unchecked_rays = 0;
};

// Shades x behind the wall with `checked` (into scratch and counters, which the caller reads) and
// with `unchecked`, adding both to `totals`; returns the checked point, with the rays it was asked.
BehindAWall compare_behind_a_wall(const lev::LevCutSelector& checked,
                                  const lev::LevCutSelector& unchecked,
                                  const std::vector<lev::Light>& lights, const glm::vec3& x,
                                  float wall_x, lev::SelectorScratch& scratch,
                                  lev::SelectionCounters& counters, CheckAgainstNone& totals) {
  BehindAWall point(x, wall_x);
  const glm::vec3 radiance = checked.direct_radiance(point, scratch, counters);
  totals.checked_error += std::abs(radiance.x - point.truth(lights));
  totals.checked_tested += counters.lights_tested;
  totals.checked_rays += counters.shadow_rays;
  BehindAWall same(x, wall_x);
  lev::SelectorScratch plain;
  lev::SelectionCounters once;
  totals.unchecked_error +=
      std::abs(unchecked.direct_radiance(same, plain, once).x - same.truth(lights));
  totals.unchecked_tested += once.lights_tested;
  totals.unchecked_rays += once.shadow_rays;
  return point;
}

// The rig of fixtures half behind a wall that runs through its fixtures: clusters with some
// lights seen and some hidden, each shaded through one 0/1 ray. The noise check cuts finer at
// such points (more lights tested), and the radiance comes nearer the truth (the seen lights'
// sum) over the points; a ray to a position asked already at the point is answered again, not
// cast: no position is asked twice, the shadow rays counted are the rays the point was asked
// for, and lights_tested is the size of the cut shaded. Where every light is seen the check
// changes nothing.
TEST(LevCut, TheNoiseCheckCutsFinerWhereTheRaysFindClustersPartlyHidden) {
  const lev::LightDescription tree = rig_of_fixtures();
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
  const lev::LevCutSelector checked(h, 0.05f);
  const lev::LevCutSelector unchecked(h, 0.05f, 1.0f, 0.0);
  CheckAgainstNone totals;
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 x(0.37f * static_cast<float>(k), 7.1f, 2.0f);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const BehindAWall point =
        compare_behind_a_wall(checked, unchecked, world_lights, x,
                              3.05f + 0.2f * static_cast<float>(k % 7), scratch, counters, totals);
    ASSERT_EQ(static_cast<std::uint64_t>(point.rays), counters.shadow_rays) << k;
    ASSERT_EQ(point.asked_again, 0) << k;
    // The cut shaded, not every round's: a refined cut replaces the last.
    ASSERT_EQ(counters.lights_tested, scratch.lights.size()) << k;
  }
  EXPECT_GT(totals.checked_tested, totals.unchecked_tested + totals.unchecked_tested / 2);
  EXPECT_LT(totals.checked_error, 0.5 * totals.unchecked_error);
  EXPECT_GT(totals.checked_rays, totals.unchecked_rays);
  // Every light seen: no refinement, the same radiance and work.
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 x(0.8f * static_cast<float>(k), 5.0f, -3.0f);
    lev::SelectorScratch scratch;
    lev::SelectionCounters a, b;
    UnitResponsePoint point(x);
    const glm::vec3 with_check = checked.direct_radiance(point, scratch, a);
    const glm::vec3 without = unchecked.direct_radiance(point, scratch, b);
    EXPECT_EQ(with_check, without) << k;
    EXPECT_EQ(a.lights_tested, b.lights_tested) << k;
    EXPECT_EQ(a.shadow_rays, b.shadow_rays) << k;
  }
}

// Eight fixtures of 40 spots aimed apart (a ring, each spot tilted out): a cluster of a fixture is
// neither centred (its axes spread) nor exact (more than kExactClusterLights): a drawn one.
lev::LightDescription fixtures_of_forty_spots_aimed_apart() {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> spots;
  for (int k = 0; k < 40; ++k) {
    const float azimuth = 0.15707963f * static_cast<float>(k);
    const glm::vec3 aim(0.766f * std::cos(azimuth), 0.766f * std::sin(azimuth), -0.643f);
    spots.push_back(lev::light_node(
        lev::make_spot_light(glm::vec3(2.0f * std::cos(azimuth), 2.0f * std::sin(azimuth), 0.0f),
                             aim, glm::vec3(40.0f), 1.2f, 0.0f)));
  }
  tree.masters.push_back(lev::union_node(std::move(spots)));
  std::vector<lev::LightDescriptionNode> fixtures;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 at(6.0f * static_cast<float>(k), 0.0f, 10.0f);
    fixtures.push_back(lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  tree.root = lev::union_node(std::move(fixtures));
  return tree;
}

// A drawn cluster's one ray stands for its forty lights as a centred one's does: a wall through
// the fixtures makes the check refine there too (it counted centred and exact clusters alone).
// Every cluster of the cut is one the noise counts.
TEST(LevCut, TheNoiseCheckCountsDrawnClustersOfManyLights) {
  const lev::LightDescription tree = fixtures_of_forty_spots_aimed_apart();
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
  const lev::LevCutSelector checked(h, 0.5f);
  const lev::LevCutSelector unchecked(h, 0.5f, 1.0f, 0.0);
  CheckAgainstNone totals;
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 x(2.4f * static_cast<float>(k) - 2.0f, 1.0f, 0.0f);
    lev::SelectorScratch scratch;
    lev::InspectRecord record;
    scratch.inspect = &record;
    scratch.walk.inspect = &record;
    lev::SelectionCounters counters;
    compare_behind_a_wall(checked, unchecked, world_lights, x, 6.0f * static_cast<float>(k % 8),
                          scratch, counters, totals);
    std::size_t several = 0;
    for (const lev::ShadedLight& s : record.shaded) several += s.walk_cluster >= 0;
    EXPECT_EQ(scratch.walk.several_light_clusters.size(), several) << k;
  }
  EXPECT_GT(totals.checked_tested, totals.unchecked_tested);
  EXPECT_LT(totals.checked_error, totals.unchecked_error);
}

// Lights each below its own translation: the cut's kept subtrees are clusters of one light, whose
// ray goes to that light, exact: nothing to refine, whatever the wall hides (less than half of
// the total at each point, which the hidden check would refine for).
TEST(LevCut, TheNoiseCheckLeavesClustersOfOneLight) {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> lights;
  for (int k = 0; k < 20; ++k) {
    lights.push_back(lev::affine_node(
        lev::make_translation({1.5f * static_cast<float>(k), 0.0f, 6.0f}),
        lev::light_node(lev::make_point_light(glm::vec3(0.0f), glm::vec3(40.0f)))));
  }
  tree.root = lev::union_node(std::move(lights));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const lev::LevCutSelector checked(h, 0.3f);
  const lev::LevCutSelector unchecked(h, 0.3f, 1.0f, 0.0);
  std::uint64_t singles = 0;
  for (int k = 0; k < 10; ++k) {
    const glm::vec3 x(1.5f * static_cast<float>(k), 2.0f, 0.0f);
    lev::SelectorScratch scratch;
    lev::SelectionCounters a, b;
    BehindAWall p(x, 1.5f * static_cast<float>(k) - 0.7f);
    BehindAWall q(x, 1.5f * static_cast<float>(k) - 0.7f);
    const glm::vec3 with_check = checked.direct_radiance(p, scratch, a);
    singles += scratch.walk.exact_clusters.size();
    lev::SelectorScratch plain;
    EXPECT_EQ(with_check, unchecked.direct_radiance(q, plain, b)) << k;
    EXPECT_EQ(a.nodes_visited, b.nodes_visited) << k;
    EXPECT_EQ(a.lights_tested, b.lights_tested) << k;
  }
  EXPECT_GT(singles, 0u);
}

// After a refinement the inspector lists the last cut alone: its shaded lights are the cut's,
// their contributions sum to the radiance, its clusters are the walk's, and with what was dropped
// they hold every light once.
TEST(LevCut, AfterTheNoiseCheckTheInspectorListsTheLastCut) {
  lev::LightDescription tree = rig_of_fixtures();
  // Far fixtures, below the tolerance at every point: dropped by the volumes in the first cut.
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 at(300.0f + 2.0f * static_cast<float>(k), 0.0f, 10.0f);
    tree.root.children.push_back(
        lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const std::size_t light_count = lev::flatten_light_description(tree).size();
  const lev::LevCutSelector checked(h, 0.05f);
  const lev::LevCutSelector unchecked(h, 0.05f, 1.0f, 0.0);
  int refined = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 x(0.37f * static_cast<float>(k), 7.1f, 2.0f);
    const float wall_x = 3.05f + 0.2f * static_cast<float>(k % 7);
    BehindAWall point(x, wall_x);
    lev::SelectorScratch scratch;
    lev::InspectRecord record;
    scratch.inspect = &record;
    scratch.walk.inspect = &record;
    lev::SelectionCounters counters;
    const glm::vec3 radiance = checked.direct_radiance(point, scratch, counters);
    ASSERT_EQ(record.shaded.size(), scratch.lights.size()) << k;
    glm::dvec3 sum(0.0);
    std::size_t cluster_entries = 0;
    for (const lev::ShadedLight& s : record.shaded) {
      sum += glm::dvec3(s.contribution);
      cluster_entries += s.walk_cluster >= 0;
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], radiance[c], 1e-5 * (1.0 + sum[c])) << k;
    EXPECT_EQ(cluster_entries, record.walk_clusters.size()) << k;
    // Every light once: shaded, in a cluster of the last cut, or dropped by a cut before (a
    // refined cut goes on from the last one and keeps what it dropped).
    lev::complete_inspection(h, point, record);
    std::size_t accounted = record.culled.size();
    for (const lev::ShadedLight& s : record.shaded)
      accounted += s.role == lev::InspectRole::cluster ? s.members.size() : 1;
    EXPECT_EQ(accounted, light_count) << k;
    lev::SelectorScratch plain;
    lev::SelectionCounters once;
    BehindAWall same(x, wall_x);
    unchecked.direct_radiance(same, plain, once);
    if (counters.lights_tested > once.lights_tested) ++refined;
  }
  EXPECT_GT(refined, 5);
}

// A wall hides every light on the near side of the plane x = wall_x, on every channel; the
// truth is the sum over every light the wall leaves seen.
class WallOnEveryChannel final : public UnitResponsePoint {
 public:
  WallOnEveryChannel(const glm::vec3& x, float wall_x) : UnitResponsePoint(x), wall_x_(wall_x) {}
  bool visible(const lev::Light& target) override { return target.position.x > wall_x_; }
  glm::dvec3 truth(const std::vector<lev::Light>& lights) const {
    glm::dvec3 sum(0.0);
    for (const lev::Light& l : lights) {
      if (l.position.x > wall_x_) sum += glm::dvec3(lev::irradiance(l, position()));
    }
    return sum;
  }

 private:
  float wall_x_;
};

// What shade_behind_the_wall found: the radiance and the selector's counters.
struct ShadedBehindTheWall {
  glm::vec3 radiance{0.0f};
  lev::SelectionCounters counters;
};

// x shaded by `selector` behind a wall at wall_x on every channel, its culled bounds asked for and
// the inspector on: the error against every light with the wall's shadows is within both bounds
// (relative slack 1e-4, absolute `floor`), and the inspector holds every light once (shaded, in a
// cluster of the last cut, or dropped). A fatal failure ends it: the caller checks.
void shade_behind_the_wall(const lev::LevCutSelector& selector, const lev::LightHierarchy& h,
                           const std::vector<lev::Light>& world_lights, const glm::vec3& x,
                           float wall_x, double floor, const std::string& context,
                           ShadedBehindTheWall& shaded) {
  WallOnEveryChannel point(x, wall_x);
  lev::SelectorScratch scratch;
  lev::CulledRadianceBound culled_radiance;
  scratch.culled_radiance = &culled_radiance;
  lev::InspectRecord record;
  scratch.inspect = &record;
  scratch.walk.inspect = &record;
  glm::vec3 irradiance_bound(-1.0f);
  shaded.radiance = selector.direct_radiance(point, scratch, shaded.counters, &irradiance_bound);
  ASSERT_TRUE(culled_radiance.bounded) << context;
  const glm::dvec3 truth = point.truth(world_lights);
  for (int c = 0; c < 3; ++c) {
    const double error = std::abs(static_cast<double>(shaded.radiance[c]) - truth[c]);
    const double slack = 1e-4 * truth[c] + floor;
    ASSERT_LE(error, static_cast<double>(culled_radiance.bound[c]) * (1.0 + 1e-4) + slack)
        << context << ", channel " << c;
    ASSERT_LE(error, static_cast<double>(irradiance_bound[c]) * (1.0 + 1e-4) + slack)
        << context << ", channel " << c;
  }
  ASSERT_EQ(record.shaded.size(), scratch.lights.size()) << context;
  lev::complete_inspection(h, point, record);
  std::size_t accounted = record.culled.size();
  for (const lev::ShadedLight& s : record.shaded)
    accounted += s.role == lev::InspectRole::cluster ? s.members.size() : 1;
  ASSERT_EQ(accounted, world_lights.size()) << context;
}

// After the noise check's refinements (each going on from the last cut) the culled bounds the
// selector answers, for the last cut, still hold its error against every light with the wall's
// shadows: the radiance bound (clusters' error on top of what the volumes dropped) and the
// irradiance bound (a unit response); the inspector holds every light once.
TEST(LevCut, AfterRefinementsTheErrorIsWithinTheCulledBounds) {
  std::uint64_t refined = 0, points = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = seed == 1   ? rig_of_fixtures()
                                       : seed == 2 ? fixtures_of_forty_spots_aimed_apart()
                                       : seed == 3 ? fixtures_of_spots_aimed_apart()
                                                   : lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    float low = world_lights.front().position.x, high = low;
    for (const lev::Light& l : world_lights) {
      low = std::min(low, l.position.x);
      high = std::max(high, l.position.x);
    }
    for (const float relative_error : {0.02f, 0.3f, 1.0f}) {
      const lev::LevCutSelector checked(h, relative_error);
      const lev::LevCutSelector unchecked(h, relative_error, 1.0f, 0.0);
      for (int k = 0; k < 40; ++k) {
        const glm::vec3 x(r.uniform(low, high), r.uniform(-10, 10), r.uniform(-5, 5));
        const float wall_x = r.uniform(low, high);
        const std::string context = "seed " + std::to_string(seed) + " relative error " +
                                    std::to_string(relative_error) + " k " + std::to_string(k);
        ShadedBehindTheWall shaded;
        shade_behind_the_wall(checked, h, world_lights, x, wall_x, 1e-9, context, shaded);
        if (HasFatalFailure()) return;
        WallOnEveryChannel same(x, wall_x);
        lev::SelectorScratch plain;
        lev::SelectionCounters once;
        unchecked.direct_radiance(same, plain, once);
        ++points;
        if (shaded.counters.lights_tested != once.lights_tested) ++refined;
      }
    }
  }
  EXPECT_GT(refined, points / 20) << points;
}

// Two instances of a panel of 2,500 dim lights (one turned and scaled), each light below the
// drop's tolerance, and a few bright lights: the drop often exceeds its budget, so the point is
// walked again. After that walk (and the noise check's refinements) the culled bounds still hold
// the error against every light with the wall's shadows, the inspector holds every light once
// (the first walk's records are gone), and the same point gives the same radiance again; at
// exposures 2^8 and 2^-8 alike (the intensities scaled to match).
lev::LightDescription dim_panels_and_bright_lights(Random& r, float scale) {
  lev::LightDescription tree;
  std::vector<lev::Light> panel;
  for (int k = 0; k < 2500; ++k) {
    const glm::vec3 at(0.2f * static_cast<float>(k % 50) - 5.0f,
                       0.2f * static_cast<float>(k / 50) - 5.0f, 3.0f);
    panel.push_back(lev::make_point_light(at, glm::vec3(2e-4f, 1e-4f, 5e-5f) * scale));
  }
  tree.masters.push_back(lev::build_light_bvh(panel));
  std::vector<lev::LightDescriptionNode> children;
  children.push_back(
      lev::affine_node(lev::make_translation({0.0f, 0.0f, 0.5f}), lev::instance_node(0)));
  children.push_back(lev::affine_node(
      lev::compose(lev::make_rotation({1.0f, 1.0f, 0.0f}, 0.3f), lev::make_scale(1.5f)),
      lev::instance_node(0)));
  for (int k = 0; k < 3; ++k) {
    const glm::vec3 at(r.uniform(-6, 6), r.uniform(-6, 6), r.uniform(4, 8));
    children.push_back(
        lev::light_node(lev::make_point_light(at, glm::vec3(r.uniform(0.05f, 1.0f)) * scale)));
  }
  tree.root = lev::union_node(std::move(children));
  return tree;
}

TEST(LevCut, AfterASecondWalkTheErrorIsWithinTheCulledBoundsAndEveryLightIsCountedOnce) {
  std::uint64_t walked_again = 0, points = 0;
  for (const float display_scale : {1.0f, 256.0f, 1.0f / 256.0f}) {
    Random r(7);
    const lev::LightDescription tree = dim_panels_and_bright_lights(r, 1.0f / display_scale);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const lev::CutNodeTable table = lev::make_cut_node_table(h);
    const std::vector<lev::Light> world_lights = lev::flatten_light_description(tree);
    for (const float relative_error : {0.02f, 0.3f, 1.0f}) {
      const lev::LevCutSelector selector(h, relative_error, display_scale);
      const float tolerance = relative_error * lev::kDropToleranceOfRelativeError / display_scale;
      const lev::ExtentVolumes volumes = lev::fit_extent_volumes(h, tolerance);
      for (int k = 0; k < 20; ++k) {
        const glm::vec3 x(r.uniform(-6, 6), r.uniform(-6, 6), r.uniform(-4, 2));
        const float wall_x = r.uniform(-6, 6);
        const std::string context = "display scale " + std::to_string(display_scale) +
                                    " relative error " + std::to_string(relative_error) + " k " +
                                    std::to_string(k);
        // Walked again: the cut differs from the one whose drop has no budget (white at inf).
        UnitResponsePoint unit(x);
        lev::WalkScratch walk;
        std::vector<lev::Light> budgeted, unbudgeted;
        lev::WalkCounters counters_budgeted, counters_unbudgeted;
        lev::find_light_cut(h, volumes, table, tolerance, relative_error, unit, walk, budgeted,
                            counters_budgeted, nullptr, 1.0f / display_scale);
        lev::find_light_cut(h, volumes, table, tolerance, relative_error, unit, walk, unbudgeted,
                            counters_unbudgeted, nullptr, std::numeric_limits<float>::infinity());
        if (counters_budgeted.nodes_visited != counters_unbudgeted.nodes_visited) ++walked_again;
        ShadedBehindTheWall shaded;
        shade_behind_the_wall(selector, h, world_lights, x, wall_x, 1e-12, context, shaded);
        if (HasFatalFailure()) return;
        WallOnEveryChannel same(x, wall_x);
        lev::SelectorScratch again;
        lev::SelectionCounters counters_again;
        EXPECT_EQ(selector.direct_radiance(same, again, counters_again), shaded.radiance)
            << context;
        EXPECT_EQ(counters_again.nodes_visited, shaded.counters.nodes_visited) << context;
        ++points;
      }
    }
  }
  EXPECT_GT(walked_again, points / 4) << points;
}

// Twenty fixtures, each a light above the drop's tolerance among 100 dim lights below it, and a
// light near the points: each fixture is a cluster of the first cut (no drop, so no second walk)
// and is opened by a finer one (refine_light_cut), whose volumes then drop the dim lights.
lev::LightDescription fixtures_of_a_light_among_dim_ones() {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> parts;
  parts.push_back(lev::light_node(lev::make_point_light({0.0f, 0.0f, 0.0f}, glm::vec3(0.05f))));
  std::vector<lev::Light> dim;
  for (int k = 0; k < 100; ++k) {
    const glm::vec3 at(0.05f * static_cast<float>(k % 10), 0.05f * static_cast<float>(k / 10),
                       0.3f);
    dim.push_back(lev::make_point_light(at, glm::vec3(5e-3f)));
  }
  parts.push_back(lev::build_light_bvh(dim));
  tree.masters.push_back(lev::union_node(std::move(parts)));
  std::vector<lev::LightDescriptionNode> fixtures;
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 at(2.0f * static_cast<float>(k % 5) - 4.0f, 2.0f * static_cast<float>(k / 5),
                       10.0f);
    fixtures.push_back(lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  fixtures.push_back(lev::light_node(lev::make_point_light({0.0f, 0.0f, 1.0f}, glm::vec3(0.4f))));
  tree.root = lev::union_node(std::move(fixtures));
  return tree;
}

// A finer cut going on from one that was not walked again holds what its volumes drop within the
// first cut's budget too (the relative error of the total, or the floor): it had no budget, and
// dropped every fixture's dim lights (error 20-29 % at relative error 0.02, both directly and
// through the noise check's refinements behind a wall).
TEST(LevCut, AFinerCutHoldsItsDropWithinTheBudget) {
  const CutScene scene(fixtures_of_a_light_among_dim_ones());
  const float relative_error = 0.02f;
  const float tau = relative_error * lev::kDropToleranceOfRelativeError;
  const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.h, tau);
  const lev::LevCutSelector selector(scene.h, relative_error);
  const lev::LevCutSelector unchecked(scene.h, relative_error, 1.0f, 0.0);
  lev::WalkScratch scratch;
  Random r(3);
  int refined = 0;
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 x(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-0.5f, 0.5f));
    UnitResponsePoint point(x);
    std::vector<lev::Light> cut;
    lev::WalkCounters counters;
    lev::start_light_cut(scene.h, volumes, scene.table, tau, relative_error, point, scratch, cut,
                         counters, true, false, 1.0f);
    const float within = std::max(relative_error * lev::brightest(scratch.cut_sums.total),
                                  relative_error * lev::kTotalFloorOfWhite);
    lev::refine_light_cut(scene.h, volumes, scene.table, tau, 0.5f * relative_error, point, scratch,
                          cut, counters, false);
    EXPECT_LE(lev::brightest(scratch.cut_sums.dropped), within * (1.0f + 1e-5f)) << k;
    glm::dvec3 estimate(0.0);
    for (const glm::vec3& e : scratch.cut_estimates) estimate += glm::dvec3(e);
    const double exact = summed_irradiance(scene.world_lights, x).x;
    EXPECT_NEAR(estimate.x, exact, 2.0 * relative_error * exact) << k;
    // Through the noise check: the wall hides some fixtures' lights, so their clusters are noisy.
    const float wall_x = r.uniform(-4, 4);
    BehindAWall walled(x, wall_x);
    lev::SelectorScratch selector_scratch;
    lev::SelectionCounters selected;
    const glm::vec3 radiance = selector.direct_radiance(walled, selector_scratch, selected);
    EXPECT_NEAR(radiance.x, walled.truth(scene.world_lights), 3.0 * relative_error * exact) << k;
    BehindAWall same(x, wall_x);
    lev::SelectorScratch plain;
    lev::SelectionCounters once;
    unchecked.direct_radiance(same, plain, once);
    if (selected.lights_tested != once.lights_tested) ++refined;
  }
  EXPECT_GT(refined, 5);
}

// At the smallest relative error above 0 the noise check cannot halve it (half of it rounds to
// 0, where nothing is cut and no estimates are kept): a refinement there would leave the cut's
// estimates apart from its lights (and assert in refine_light_cut). Dim fixtures half behind a
// wall beside a light bright enough that their clusters stay within that relative error.
TEST(LevCut, TheNoiseCheckStopsWhereHalfTheRelativeErrorIsZero) {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> quarters;
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 at(0.3f * static_cast<float>(k % 2), 0.3f * static_cast<float>(k / 2), 0.0f);
    quarters.push_back(lev::light_node(lev::make_point_light(at, glm::vec3(1e-12f))));
  }
  tree.masters.push_back(lev::union_node(std::move(quarters)));
  std::vector<lev::LightDescriptionNode> root;
  root.push_back(lev::light_node(lev::make_point_light({20.0f, 0.0f, 1.0f}, glm::vec3(1e37f))));
  for (int k = 0; k < 16; ++k) {
    const glm::vec3 at(2.0f * static_cast<float>(k % 4), 2.0f * static_cast<float>(k / 4), 10.0f);
    root.push_back(lev::affine_node(lev::make_translation(at), lev::instance_node(0)));
  }
  tree.root = lev::union_node(std::move(root));
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  const float smallest = std::numeric_limits<float>::denorm_min();
  ASSERT_EQ(smallest * 0.5f, 0.0f);
  const lev::LevCutSelector checked(h, smallest);
  std::uint64_t clustered = 0;
  for (int k = 0; k < 16; ++k) {
    const glm::vec3 x(0.4f * static_cast<float>(k), 3.0f, 0.0f);
    BehindAWall point(x, 0.15f + 2.0f * static_cast<float>(k % 4));
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    checked.direct_radiance(point, scratch, counters);
    clustered += scratch.walk.several_light_clusters.size();
    ASSERT_EQ(scratch.walk.cut_estimates.size(), scratch.lights.size()) << k;
  }
  EXPECT_GT(clustered, 0u);
}

// A light a million times brighter than each of 200 dim ones, behind a wall (x < 0) that leaves
// the dim grid seen: the cut is made relative to a total the wall hides, so at first the grid is
// one coarse cluster. The hidden check refines it relative to what the rays show: the error is
// within the relative error of the seen lights' sum, and is far larger without the check.
TEST(LevCut, TheHiddenCheckCutsRelativeToWhatTheRaysShow) {
  lev::LightDescription tree;
  std::vector<lev::Light> dim;
  for (int k = 0; k < 200; ++k) {
    const glm::vec3 at(1.0f + 0.2f * static_cast<float>(k % 20), 1.0f * static_cast<float>(k / 20),
                       3.0f);
    dim.push_back(lev::make_point_light(at, glm::vec3(1.0f)));
  }
  std::vector<lev::LightDescriptionNode> root;
  root.push_back(lev::build_light_bvh(dim));
  root.push_back(lev::light_node(lev::make_point_light({-2.0f, 5.0f, 3.0f}, glm::vec3(1e6f))));
  tree.root = lev::union_node(std::move(root));
  const CutScene scene(tree);
  const float relative_error = 0.02f;
  const lev::LevCutSelector checked(scene.h, relative_error);
  const lev::LevCutSelector unchecked(scene.h, relative_error, 1.0f, 0.0);
  double worst_checked = 0.0, worst_unchecked = 0.0;
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 x(0.3f * static_cast<float>(k), 0.5f * static_cast<float>(k), 0.0f);
    BehindAWall point(x, 0.0f);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const double truth = point.truth(scene.world_lights);
    const double error = std::abs(checked.direct_radiance(point, scratch, counters).x - truth);
    worst_checked = std::max(worst_checked, error / truth);
    ASSERT_EQ(scratch.walk.cut_estimates.size(), scratch.lights.size()) << k;
    BehindAWall same(x, 0.0f);
    lev::SelectorScratch plain;
    lev::SelectionCounters once;
    worst_unchecked = std::max(
        worst_unchecked, std::abs(unchecked.direct_radiance(same, plain, once).x - truth) / truth);
  }
  EXPECT_LE(worst_checked, relative_error);
  EXPECT_GT(worst_unchecked, 5.0 * relative_error);
}

// One scratch shading with the selectors of two hierarchies alike in shape (the same nodes) but
// with their lights moved and brightened: each gives what it gives with a scratch of its own, so
// the representatives and shadow targets the scratch keeps (PlacedLightMemo) are never the other
// hierarchy's.
TEST(LevCut, AScratchReusedWithAnotherHierarchyKeepsNoneOfItsLights) {
  Random r(17);
  const lev::LightDescription first_tree = rig_of_fixtures();
  lev::LightDescription second_tree = first_tree;
  // Every light of the masters (the fixtures) moved and made brighter; the shape stays.
  std::vector<lev::LightDescriptionNode*> open;
  for (lev::LightDescriptionNode& master : second_tree.masters) open.push_back(&master);
  while (!open.empty()) {
    lev::LightDescriptionNode* node = open.back();
    open.pop_back();
    if (node->kind == lev::NodeKind::point_light || node->kind == lev::NodeKind::spot_light) {
      node->light.intensity *= 3.0f;
      node->light.position += glm::vec3(0.2f, -0.1f, 0.05f);
    }
    for (lev::LightDescriptionNode& child : node->children) open.push_back(&child);
  }
  const lev::LightHierarchy first = lev::build_hierarchy(first_tree);
  const lev::LightHierarchy second = lev::build_hierarchy(second_tree);
  ASSERT_EQ(first.nodes.size(), second.nodes.size());
  const lev::LevCutSelector first_cut(first, 0.05f);
  const lev::LevCutSelector second_cut(second, 0.05f);
  lev::SelectorScratch shared;
  int differing = 0;
  for (int k = 0; k < 30; ++k) {
    const glm::vec3 x(r.uniform(0, 10), r.uniform(0, 10), r.uniform(-3, 1));
    const float wall_x = r.uniform(2, 8);
    for (const lev::LevCutSelector* selector : {&first_cut, &second_cut}) {
      BehindAWall point(x, wall_x), same(x, wall_x);
      lev::SelectionCounters a, b;
      lev::SelectorScratch own;
      const glm::vec3 with_shared = selector->direct_radiance(point, shared, a);
      ASSERT_EQ(with_shared, selector->direct_radiance(same, own, b)) << k;
    }
    BehindAWall p(x, wall_x), q(x, wall_x);
    lev::SelectionCounters a, b;
    lev::SelectorScratch one, two;
    if (first_cut.direct_radiance(p, one, a) != second_cut.direct_radiance(q, two, b)) ++differing;
  }
  EXPECT_GT(differing, 20);
}

// The errors of cut_against_the_truth's points: signed, summed, and the truth summed.
struct SignedError {
  double signed_sum = 0.0, truth_sum = 0.0;
};

// lev_cut at relative_error (no noise check: every light is seen) on 40 points drawn by `seed`
// over [0, width]^2 x [0, height], each within twice the relative error of the summed irradiance
// of every light of the scene.
SignedError cut_against_the_truth(const CutScene& scene, float relative_error, std::uint64_t seed,
                                  float width, float height) {
  const lev::LevCutSelector selector(scene.h, relative_error, 1.0f, 0.0);
  Random r(seed);
  SignedError error;
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 x(r.uniform(0, width), r.uniform(0, width), r.uniform(0.0f, height));
    UnitResponsePoint point(x);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    const double radiance = selector.direct_radiance(point, scratch, counters).x;
    const double truth = summed_irradiance(scene.world_lights, x).x;
    EXPECT_NEAR(radiance, truth, 2.0 * relative_error * truth) << k;
    error.signed_sum += radiance - truth;
    error.truth_sum += truth;
  }
  return error;
}

// A lamp master of a dim bulb (a point light, first) and a bright spot aimed down, placed 256
// times: a centred representative takes its first light's kind with the whole intensity, so every
// lamp's spot shone as a point light everywhere, the same way in every instance (classteam D1:
// every pixel too bright, 3.7 % on average at relative error 0.02). A small cluster whose lights
// do not shine alike is shaded from its own lights instead: within the relative error of the
// truth at points under the lamps and beside them, and no brighter on average.
TEST(LevCut, ASmallClusterOfLightsThatShineDifferentlyIsShadedFromItsOwnLights) {
  lev::LightDescription tree;
  std::vector<lev::LightDescriptionNode> lamp;
  lamp.push_back(lev::light_node(lev::make_point_light(glm::vec3(0.0f), glm::vec3(0.02f))));
  lamp.push_back(lev::light_node(lev::make_spot_light({0.0f, 0.0f, -0.1f}, {0.0f, 0.0f, -1.0f},
                                                      glm::vec3(0.15f), 1.0471976f, 2.0f)));
  tree.masters.push_back(lev::union_node(std::move(lamp)));
  std::vector<lev::BvhItem> lamps;
  for (int k = 0; k < 256; ++k) {
    const glm::vec3 at(1.5f * static_cast<float>(k % 16), 1.5f * static_cast<float>(k / 16), 3.0f);
    lev::LightDescriptionNode node =
        lev::affine_node(lev::make_translation(at), lev::instance_node(0));
    const std::vector<lev::SubtreeLights> master_lights = {
        lev::subtree_lights(tree.masters[0], {})};
    const lev::SubtreeLights lights = lev::subtree_lights(node, master_lights);
    lamps.push_back({std::move(node), lights});
  }
  tree.root = lev::build_bvh(std::move(lamps));
  const float relative_error = 0.02f;
  const SignedError error = cut_against_the_truth(CutScene(tree), relative_error, 23, 22.0f, 2.0f);
  EXPECT_LT(error.signed_sum, 0.5 * relative_error * error.truth_sum);
}

// Point lights whose ranges differ (every other one dark beyond 3.2 units, the rest unlimited):
// a centred representative takes its first light's range, so a cluster went dark, or lit, with
// its first light beyond that range (classteam's ranges.json: max error 4.84 % at relative error
// 0.02). Ranges count in whether lights shine alike: within the relative error of the truth.
TEST(LevCut, ASmallClusterOfLightsOfDifferentRangesIsShadedFromItsOwnLights) {
  std::vector<lev::Light> lights;
  for (int k = 0; k < 256; ++k) {
    lev::Light light = lev::make_point_light(
        {0.5f * static_cast<float>(k % 16), 0.5f * static_cast<float>(k / 16), 3.0f},
        glm::vec3(0.05f));
    if (k % 2 == 0) light.range = 3.2f;
    lights.push_back(light);
  }
  lev::LightDescription tree;
  tree.root = lev::build_light_bvh(lights);
  cut_against_the_truth(CutScene(tree), 0.02f, 29, 8.0f, 1.0f);
}

TEST(LevCut, InTheMethodTableSweptOverTheRelativeError) {
  const std::optional<lev::Method> method = lev::parse_method("lev_cut");
  ASSERT_TRUE(method.has_value());
  const lev::MethodInfo& info = lev::method_info(*method);
  EXPECT_TRUE(info.uses_relative_error);
  EXPECT_FALSE(info.uses_tolerance);
  EXPECT_FALSE(info.stochastic);
  EXPECT_EQ(lev::swept_setting(info), &lev::MethodParams::relative_error);
}

}  // namespace
