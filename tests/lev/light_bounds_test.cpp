// Light aggregates and irradiance_bound against brute force: on random instanced scenes (masters
// instancing masters through random rotations, translations and uniform scales, placed in the
// world through further nested similarities) with point lights and spotlights of 0 to 180 degrees,
// the bound of a master's aggregate, evaluated at a world point moved into the master's frame, is
// never below the summed irradiance of the master's lights in the world: at random, far and near
// points, at and next to every light, on the faces and corners of the aggregate's box. Exact
// cases check that the bound is also tight where it should be (not just infinite).
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/hierarchy_cursor.h"
#include "lev/important_lights.h"
#include "lev/light_bounds.h"
#include "lev/light_hierarchy.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

glm::dvec3 brute_force_irradiance(const std::vector<lev::Light>& world_lights, const glm::vec3& x) {
  glm::dvec3 sum(0.0);
  for (const lev::Light& l : world_lights) sum += glm::dvec3(lev::irradiance(l, x));
  return sum;
}

void expect_bound_holds(const glm::vec3& bound, const glm::dvec3& exact,
                        const std::string& context) {
  for (int c = 0; c < 3; ++c) {
    ASSERT_FALSE(std::isnan(bound[c])) << context;
    ASSERT_GE(static_cast<double>(bound[c]), exact[c]) << context << ", channel " << c;
  }
}

// A master placed in the world through 1 to 3 nested random similarities (outermost first).
struct Placement {
  std::vector<lev::Similarity> chain;
  lev::Similarity world_from_master;
};

Placement random_placement(Random& r) {
  Placement p;
  const int depth = r.integer(1, 3);
  for (int i = 0; i < depth; ++i) {
    p.chain.push_back(lev_test::random_similarity(r));
    p.world_from_master = lev::compose(p.world_from_master, p.chain.back());
  }
  return p;
}

lev::FramePoint in_master_frame(const Placement& p, const glm::vec3& world_point) {
  lev::FramePoint q = lev::world_frame_point(world_point);
  for (const lev::Similarity& xf : p.chain) q = lev::to_node_frame(q, xf);
  return q;
}

// Points that probe the bound where it is easy to get wrong, all in the world: random near and
// far, at and around every light, on the box of positions (faces, corners, just outside), and
// behind every spotlight.
std::vector<glm::vec3> probe_points(Random& r, const std::vector<lev::Light>& world_lights,
                                    const lev::Bounds& master_box,
                                    const lev::Similarity& world_from_master) {
  std::vector<glm::vec3> points;
  for (int k = 0; k < 30; ++k)
    points.push_back({r.uniform(-60, 60), r.uniform(-60, 60), r.uniform(-20, 20)});
  for (const float far : {1e3f, 1e5f, 1e7f}) points.push_back(far * r.direction());
  for (const lev::Light& l : world_lights) {
    points.push_back(l.position);
    for (const float near : {1e-3f, 0.05f, 1.0f})
      points.push_back(l.position + near * r.direction());
    if (l.kind == lev::LightKind::spot) {
      points.push_back(l.position - 0.5f * l.direction);
      points.push_back(l.position + 2.0f * l.direction);
    }
  }
  const glm::vec3 lo = master_box.lo, hi = master_box.hi, extent = hi - lo;
  for (int k = 0; k < 12; ++k) {
    glm::vec3 on_face(r.uniform(lo.x, hi.x), r.uniform(lo.y, hi.y), r.uniform(lo.z, hi.z));
    const int axis = k % 3;
    on_face[axis] = (k / 3) % 2 == 0 ? lo[axis] : hi[axis];
    points.push_back(lev::apply_point(world_from_master, on_face));
    glm::vec3 outside = on_face;
    outside[axis] += ((k / 3) % 2 == 0 ? -1.0f : 1.0f) * (1e-3f * extent[axis] + 1e-3f);
    points.push_back(lev::apply_point(world_from_master, outside));
  }
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 c((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                      (corner & 4) ? hi.z : lo.z);
    points.push_back(lev::apply_point(world_from_master, c));
  }
  return points;
}

TEST(LightBounds, MasterAggregateBoundsItsInstancedLightsEverywhere) {
  std::uint64_t finite_checks = 0;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    for (std::uint32_t m = 0; m < tree.masters.size(); ++m) {
      const Placement placement = random_placement(r);
      // The master's lights in the world, by the tree's plain recursion (no aggregate code).
      lev::LightDescription placed = tree;
      lev::LightDescriptionNode root = lev::instance_node(m);
      for (auto xf = placement.chain.rbegin(); xf != placement.chain.rend(); ++xf) {
        root = lev::affine_node(*xf, std::move(root));
      }
      placed.root = std::move(root);
      const std::vector<lev::Light> world_lights = lev::flatten_light_description(placed);
      const lev::LightAggregate* aggregate = lev::stored_aggregate(h, h.master_ranges[m].begin);
      ASSERT_NE(aggregate, nullptr);
      const lev::LightHierarchy placed_h = lev::build_hierarchy(placed);
      for (const glm::vec3& x :
           probe_points(r, world_lights, aggregate->positions, placement.world_from_master)) {
        const glm::dvec3 exact = brute_force_irradiance(world_lights, x);
        const std::string context = "seed " + std::to_string(seed) + " master " +
                                    std::to_string(m) + " x (" + std::to_string(x.x) + ", " +
                                    std::to_string(x.y) + ", " + std::to_string(x.z) + ")";
        const glm::vec3 bound = lev::irradiance_bound(*aggregate, in_master_frame(placement, x));
        expect_bound_holds(bound, exact, context);
        // The same through the hierarchy: its root is the affine chain over the instance.
        expect_bound_holds(
            lev::irradiance_bound(placed_h, placed_h.root, lev::world_frame_point(x)), exact,
            context + " (hierarchy)");
        if (HasFatalFailure()) return;
        if (std::isfinite(bound.x)) ++finite_checks;
      }
    }
  }
  // Most probes are outside the boxes: the property was checked on finite bounds, not on +inf.
  EXPECT_GT(finite_checks, 5000u);
}

// Spots of every cone from 0 to 180 degrees, with and without dropoff, bunched (one axis) and
// spread (opposite axes), seen from a sphere of directions around them: never below the brute
// force, and zero behind a bunch of narrow spots.
TEST(LightBounds, SpotConesFromZeroTo180Degrees) {
  const float angles[] = {0.0f, 1e-4f, 0.3f, 1.5707964f, 2.5f, 3.1415927f};
  const float dropoffs[] = {0.0f, 0.5f, 1.0f, 7.5f, 10000.0f};
  Random r(7);
  for (const float angle : angles) {
    for (const float dropoff : dropoffs) {
      for (const bool spread : {false, true}) {
        std::vector<lev::Light> lights;
        lev::LightAggregate a;
        for (int i = 0; i < 5; ++i) {
          const glm::vec3 axis = spread ? (i % 2 == 0 ? r.direction() : -lights.back().direction)
                                        : glm::normalize(glm::vec3(0.0f, 0.01f * i, -1.0f));
          const glm::vec3 p(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
          lights.push_back(
              lev::make_spot_light(p, axis, glm::vec3(1.0f, 2.0f, 0.5f), angle, dropoff));
          a = lev::merge_aggregates(a, lev::light_aggregate(lights.back()));
        }
        for (int k = 0; k < 400; ++k) {
          const float distance = std::pow(10.0f, r.uniform(0.4f, 4.0f));
          const glm::vec3 x = distance * r.direction();
          const std::string context = "angle " + std::to_string(angle) + " dropoff " +
                                      std::to_string(dropoff) + (spread ? " spread" : " bunched") +
                                      " k " + std::to_string(k);
          expect_bound_holds(lev::irradiance_bound(a, lev::world_frame_point(x)),
                             brute_force_irradiance(lights, x), context);
          if (HasFatalFailure()) return;
        }
        if (!spread && angle < 1.0f) {
          // Every axis points down (within 0.04 rad): well above the spots nothing shines.
          EXPECT_EQ(lev::irradiance_bound(a, lev::world_frame_point({0.0f, 0.0f, 50.0f})),
                    glm::vec3(0.0f))
              << "angle " << angle << " dropoff " << dropoff;
        }
      }
    }
  }
}

// glTF's smooth spots (full intensity inside the inner cone, whatever dropoff a file gave them)
// and ranged lights: the bound holds between the cones, on the inner cone's edge and behind them,
// for a tight bunch of spots sharing one axis (where a cone bound is tightest) and for spots
// spread among point lights.
TEST(LightBounds, SmoothSpotsAndRangesStayBelowTheBound) {
  const float outer_angles[] = {1e-4f, 0.3f, 1.48f, 2.5f, 3.1415927f};
  const float forced_dropoffs[] = {0.0f, 1.0f, 7.5f};
  const float ranges[] = {std::numeric_limits<float>::infinity(), 2.0f};
  Random r(11);
  for (const float outer : outer_angles) {
    for (const float dropoff : forced_dropoffs) {
      for (const float range : ranges) {
        for (const bool bunched : {true, false}) {
          std::vector<lev::Light> spots, lights;
          lev::LightAggregate a;
          const glm::vec3 shared_axis = r.direction();
          for (int i = 0; i < 4; ++i) {
            const float spread = bunched ? 0.01f : 1.0f;
            const glm::vec3 p(r.uniform(-spread, spread), r.uniform(-spread, spread),
                              r.uniform(-spread, spread));
            lev::Light l =
                lev::make_smooth_spot_light(p, bunched ? shared_axis : r.direction(),
                                            glm::vec3(2.0f, 1.0f, 0.5f), 0.9f * outer, outer);
            l.dropoff = dropoff;
            l.range = range;
            spots.push_back(l);
            lights.push_back(l);
            if (!bunched) {
              lights.push_back(lev::make_point_light(p + glm::vec3(0.5f), glm::vec3(0.25f)));
              lights.back().range = range;
            }
          }
          for (const lev::Light& l : lights) a = lev::merge_aggregates(a, lev::light_aggregate(l));
          for (int k = 0; k < 400; ++k) {
            // Half the probes lie just inside a spot's inner cone, where its ramp is already 1.
            const lev::Light& spot = spots[k % 4];
            const float gamma = 0.9f * outer * r.uniform(0.95f, 1.0f);
            const glm::vec3 side = glm::normalize(
                glm::cross(spot.direction, std::abs(spot.direction.z) < 0.9f ? glm::vec3(0, 0, 1)
                                                                             : glm::vec3(1, 0, 0)));
            const glm::vec3 dir = std::cos(gamma) * spot.direction + std::sin(gamma) * side;
            const float distance = std::pow(10.0f, r.uniform(0.2f, 2.0f));
            const glm::vec3 x =
                k % 2 == 0 ? spot.position + distance * dir : distance * r.direction();
            const std::string context = "outer " + std::to_string(outer) + " dropoff " +
                                        std::to_string(dropoff) + " range " +
                                        std::to_string(range) + (bunched ? " bunched" : " mixed") +
                                        " k " + std::to_string(k);
            expect_bound_holds(lev::irradiance_bound(a, lev::world_frame_point(x)),
                               brute_force_irradiance(lights, x), context);
            if (HasFatalFailure()) return;
          }
        }
      }
    }
  }
}

// The projection bound of the angle from an axis to a box (spot_cone_factor's second bound) never
// falls below the true cosine, for points far from, near, on and inside random boxes, flat ones
// included, with p at the box's corners, faces and inside.
TEST(LightBounds, ProjectionBoundsTheCosineToEveryPointOfTheBox) {
  Random r(17);
  for (int trial = 0; trial < 400; ++trial) {
    const glm::vec3 axis = r.direction();
    const glm::vec3 centre(r.uniform(-20, 20), r.uniform(-20, 20), r.uniform(-20, 20));
    glm::vec3 half(std::pow(10.0f, r.uniform(-3, 1)), std::pow(10.0f, r.uniform(-3, 1)),
                   std::pow(10.0f, r.uniform(-3, 1)));
    if (trial % 4 == 0) half[trial % 3] = 0.0f;  // a flat box (a row of lights)
    for (int k = 0; k < 40; ++k) {
      const float reach = std::pow(10.0f, r.uniform(-2, 2)) * (1.0f + glm::length(half));
      const glm::vec3 inside(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
      const glm::vec3 x = k % 8 == 0 ? centre + half * inside : centre + reach * r.direction();
      const float bound = lev::cos_angle_bound_by_projection(axis, x - centre, half);
      for (int j = 0; j < 60; ++j) {
        glm::vec3 u(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
        if (j < 8) u = glm::vec3((j & 1) ? 1 : -1, (j & 2) ? 1 : -1, (j & 4) ? 1 : -1);
        if (j >= 8 && j < 14) u[j % 3] = j < 11 ? -1.0f : 1.0f;
        const glm::dvec3 p = glm::dvec3(centre) + glm::dvec3(half) * glm::dvec3(u);
        const glm::dvec3 to = glm::dvec3(x) - p;
        const double length = glm::length(to);
        if (!(length > 0.0)) continue;
        const double cosine = glm::dot(glm::dvec3(axis), to) / length;
        ASSERT_GE(static_cast<double>(bound) + 1e-6, cosine)
            << "trial " << trial << " k " << k << " j " << j;
      }
    }
  }
}

// A flat row of spots shining down: beside the row, at its own height or just above it, no spot
// reaches the point, and the bound says so although the point lies in the sphere around the
// row's box (which alone would allow everything); below the row the bound still holds, near and
// far, inside and around the box.
TEST(LightBounds, FlatRowOfDownwardSpotsIsDarkBesideItAndBoundedBelow) {
  Random r(23);
  for (const float dropoff : {0.0f, 1.0f, 7.5f}) {
    std::vector<lev::Light> lights;
    lev::LightAggregate a;
    for (int i = 0; i < 16; ++i) {
      const glm::vec3 p(static_cast<float>(i % 4), static_cast<float>(i / 4),
                        0.01f * r.uniform(-1, 1));
      const glm::vec3 aim =
          glm::normalize(glm::vec3(0.05f * r.uniform(-1, 1), 0.05f * r.uniform(-1, 1), -1.0f));
      lights.push_back(lev::make_spot_light(p, aim, glm::vec3(1.0f), 1.0f, dropoff));
      a = lev::merge_aggregates(a, lev::light_aggregate(lights.back()));
    }
    for (const glm::vec3& beside : {glm::vec3(4.5f, 1.5f, 0.02f), glm::vec3(1.5f, -0.7f, 0.3f),
                                    glm::vec3(1.5f, 1.5f, 0.5f)}) {
      EXPECT_EQ(lev::irradiance_bound(a, lev::world_frame_point(beside)), glm::vec3(0.0f))
          << "dropoff " << dropoff << " at " << beside.x << " " << beside.y << " " << beside.z;
    }
    for (int k = 0; k < 2000; ++k) {
      const float z = k % 2 == 0 ? r.uniform(-1, 0.1f) : r.uniform(-30, 30);
      const glm::vec3 x(r.uniform(-3, 6), r.uniform(-3, 6), z);
      expect_bound_holds(lev::irradiance_bound(a, lev::world_frame_point(x)),
                         brute_force_irradiance(lights, x),
                         "dropoff " + std::to_string(dropoff) + " k " + std::to_string(k));
      if (HasFatalFailure()) return;
    }
  }
}

TEST(LightBounds, TightForOnePointLightAndForADistantCluster) {
  const lev::Light l = lev::make_point_light({1.0f, 2.0f, 3.0f}, {4.0f, 2.0f, 1.0f});
  const glm::vec3 x(1.0f, 2.0f, 13.0f);
  const glm::vec3 exact = lev::irradiance(l, x);
  const glm::vec3 bound = lev::irradiance_bound(lev::light_aggregate(l), lev::world_frame_point(x));
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(bound[c], exact[c]);
    EXPECT_LE(bound[c], exact[c] * 1.01f);
  }
  // 100 lights in a unit box seen from 1000 units: within 0.5% of the sum.
  Random r(3);
  std::vector<lev::Light> lights;
  lev::LightAggregate a;
  for (int i = 0; i < 100; ++i) {
    lights.push_back(lev::make_point_light({r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1)},
                                           glm::vec3(1.0f)));
    a = lev::merge_aggregates(a, lev::light_aggregate(lights.back()));
  }
  const glm::vec3 far(1000.0f, 0.0f, 0.0f);
  const glm::dvec3 sum = brute_force_irradiance(lights, far);
  const glm::vec3 cluster = lev::irradiance_bound(a, lev::world_frame_point(far));
  EXPECT_GE(cluster.x, sum.x);
  EXPECT_LE(cluster.x, sum.x * 1.005);
}

TEST(LightBounds, InsideTheBoxOfPointLightsOnlyInfinityHolds) {
  lev::LightAggregate a =
      lev::merge_aggregates(lev::light_aggregate(lev::make_point_light({0, 0, 0}, {1, 0, 1})),
                            lev::light_aggregate(lev::make_point_light({2, 2, 2}, {1, 0, 1})));
  const glm::vec3 bound = lev::irradiance_bound(a, lev::world_frame_point({1.0f, 1.0f, 1.0f}));
  EXPECT_TRUE(std::isinf(bound.x));
  EXPECT_EQ(bound.y, 0.0f);  // a dark channel stays 0, never inf * 0
  EXPECT_TRUE(std::isinf(bound.z));
  // Empty and dark aggregates bound nothing.
  EXPECT_EQ(lev::irradiance_bound(lev::LightAggregate{}, lev::world_frame_point(glm::vec3(0.0f))),
            glm::vec3(0.0f));
  const lev::LightAggregate dark =
      lev::light_aggregate(lev::make_point_light({0, 0, 0}, glm::vec3(0.0f)));
  EXPECT_EQ(lev::irradiance_bound(dark, lev::world_frame_point(glm::vec3(0.0f))), glm::vec3(0.0f));
}

// A scale of s multiplies intensity by s^2 and distances by s: the aggregate of a scaled instance
// bounds the same irradiance at the same world point (thesis 4.2.2).
TEST(LightBounds, ScaledInstanceCarriesScaleSquared) {
  const lev::LightAggregate a = lev::light_aggregate(lev::make_point_light({1, 0, 0}, {2, 2, 2}));
  const lev::LightAggregate scaled = lev::transform_aggregate(a, lev::make_scale(3.0f));
  EXPECT_GE(scaled.intensity.x, 18.0f);
  EXPECT_LE(scaled.intensity.x, 18.0f * (1.0f + 1e-6f));
  const glm::vec3 x(3.0f, 6.0f, 0.0f);  // (1, 2, 0) before scaling: distance 2, scaled 6
  const float bound = lev::irradiance_bound(scaled, lev::world_frame_point(x)).x;
  EXPECT_GE(bound, 18.0f / 36.0f);
  EXPECT_LE(bound, 18.0f / 36.0f * 1.01f);
}

// Aggregates are per structure, not per instance: a building of 4^levels instanced rooms keeps
// one per master level, and hierarchy_bytes counts them.
TEST(LightBounds, AggregatesAreStoredOncePerMaster) {
  const auto building = [](int levels) {
    lev::LightDescription tree;
    tree.masters.push_back(lev::light_node(lev::make_point_light({0, 0, 1}, glm::vec3(1.0f))));
    for (int k = 1; k <= levels; ++k) {
      std::vector<lev::LightDescriptionNode> quarters;
      for (int q = 0; q < 4; ++q) {
        const float step = static_cast<float>(1 << k);
        quarters.push_back(
            lev::affine_node(lev::make_translation({step * (q % 2), step * (q / 2), 0.0f}),
                             lev::instance_node(static_cast<std::uint32_t>(k - 1))));
      }
      tree.masters.push_back(lev::union_node(std::move(quarters)));
    }
    tree.root = lev::instance_node(static_cast<std::uint32_t>(levels));
    return lev::build_hierarchy(tree);
  };
  const lev::LightHierarchy small = building(4), large = building(8);
  EXPECT_EQ(large.aggregates.size() - small.aggregates.size(), 4u);
  EXPECT_EQ(lev::hierarchy_bytes(large) - lev::hierarchy_bytes(small),
            4 * (10 * sizeof(lev::HierarchyNode) + 10 * sizeof(lev::Bounds) +
                 4 * sizeof(lev::Similarity) + 6 * sizeof(std::uint32_t) +
                 sizeof(lev::LightAggregate) + sizeof(lev::NodeRange) + sizeof(std::uint64_t)));
  // The root's aggregate holds every light, scale and translation applied.
  const lev::LightAggregate* all = lev::stored_aggregate(large, large.root);
  ASSERT_NE(all, nullptr);
  EXPECT_EQ(all->intensity.x, static_cast<float>(large.light_count));
}

}  // namespace
