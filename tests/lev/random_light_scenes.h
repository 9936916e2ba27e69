// Random light scenes for property tests (fixed seeds): lights with intensities over six decades,
// spotlights at the extremes of their parameters, and instanced trees of random similarities; a
// grid of spots aimed opposite ways, for the light trees' splits; and the check that two light
// selections are the same lights, in the same order, bit for bit.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/light_description.h"

namespace lev_test {

struct Random {
  std::mt19937_64 engine;
  explicit Random(std::uint64_t seed) : engine(seed) {}
  float uniform(float lo, float hi) {
    return std::uniform_real_distribution<float>(lo, hi)(engine);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
  glm::vec3 direction() {
    glm::vec3 d;
    do {
      d = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    } while (glm::dot(d, d) < 1e-4f || glm::dot(d, d) > 1.0f);
    return glm::normalize(d);
  }
};

inline lev::Light random_light(Random& r) {
  const glm::vec3 p(r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5));
  const float intensity = std::pow(10.0f, r.uniform(-3.0f, 3.0f));
  if (r.integer(0, 2) == 0)
    return lev::make_point_light(p, glm::vec3(intensity, 0.5f * intensity, 0.0f));
  static const float kAngles[] = {0.0f, 1e-4f, 0.3f, 1.5707964f, 2.5f, 3.1415927f};
  static const float kDropoffs[] = {0.0f, 1.0f, 7.5f, 10000.0f};
  return lev::make_spot_light(p, r.direction(), glm::vec3(intensity), kAngles[r.integer(0, 5)],
                              kDropoffs[r.integer(0, 3)]);
}

inline lev::Similarity random_similarity(Random& r) {
  lev::Similarity xf = lev::make_rotation(r.direction(), r.uniform(0.0f, 6.2831853f));
  xf = lev::compose(
      lev::make_translation({r.uniform(-20, 20), r.uniform(-20, 20), r.uniform(-5, 5)}), xf);
  return lev::compose(xf, lev::make_scale(std::pow(2.0f, r.uniform(-2.0f, 2.0f))));
}

inline lev::LightDescription random_instanced_tree(Random& r) {
  lev::LightDescription tree;
  const int masters = r.integer(1, 4);
  for (int m = 0; m < masters; ++m) {
    std::vector<lev::LightDescriptionNode> children;
    const int count = r.integer(1, 5);
    for (int c = 0; c < count; ++c) {
      if (m > 0 && r.integer(0, 1) == 0) {
        children.push_back(
            lev::affine_node(random_similarity(r),
                             lev::instance_node(static_cast<std::uint32_t>(r.integer(0, m - 1)))));
      } else {
        children.push_back(lev::extent_volume_node(
            lev::affine_node(random_similarity(r), lev::light_node(random_light(r)))));
      }
    }
    tree.masters.push_back(lev::union_node(std::move(children)));
  }
  std::vector<lev::LightDescriptionNode> roots;
  for (int i = 0; i < 4; ++i) {
    roots.push_back(lev::affine_node(
        random_similarity(r),
        lev::instance_node(static_cast<std::uint32_t>(r.integer(0, masters - 1)))));
  }
  tree.root = lev::union_node(std::move(roots));
  return tree;
}

// At each of 64 places of a grid (z = 10) a spot aimed up and then one aimed down, the down one
// moved by `offset`: a split by position alone (or by the middle of the list) puts both ways into
// each part.
inline std::vector<lev::Light> opposite_spot_grid(const glm::vec3& offset = glm::vec3(0.0f)) {
  std::vector<lev::Light> lights;
  for (int k = 0; k < 64; ++k) {
    const glm::vec3 at(static_cast<float>(k % 8), static_cast<float>(k / 8), 10.0f);
    lights.push_back(lev::make_spot_light(at, {0, 0, 1}, glm::vec3(1.0f), 0.4f, 2.0f));
    lights.push_back(lev::make_spot_light(at + offset, {0, 0, -1}, glm::vec3(1.0f), 0.4f, 2.0f));
  }
  return lights;
}

// Same count, order, positions, intensities and directions; `context` names the case on failure.
inline void expect_same_lights(const std::vector<lev::Light>& found,
                               const std::vector<lev::Light>& expected,
                               const std::string& context) {
  ASSERT_EQ(found.size(), expected.size()) << context;
  for (std::size_t i = 0; i < found.size(); ++i) {
    ASSERT_EQ(found[i].position, expected[i].position) << context << ", light " << i;
    ASSERT_EQ(found[i].intensity, expected[i].intensity) << context << ", light " << i;
    ASSERT_EQ(found[i].direction, expected[i].direction) << context << ", light " << i;
  }
}

// Two lights at the same place with the same intensity and direction (what a selector's lights are
// matched by against the brute force's).
inline bool same_light_placement(const lev::Light& a, const lev::Light& b) {
  return a.position == b.position && a.intensity == b.intensity && a.direction == b.direction;
}

}  // namespace lev_test
