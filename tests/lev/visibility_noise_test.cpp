// visibility_noise: the binomial noise of a cut's 0/1 shadow rays over its clusters of several
// lights, sqrt(p (1 - p) sum u^2) with p the visible share the rays found, pooled; single lights
// carry none.
#include "lev/visibility_noise.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace {

lev::CutCluster centred_at(std::size_t index) {
  lev::CutCluster c;
  c.index = index;
  return c;
}

TEST(VisibilityNoise, LightsAloneAndClustersAllSeenOrAllHiddenAreExact) {
  const std::vector<glm::vec3> estimates = {glm::vec3(1.0f), glm::vec3(2.0f), glm::vec3(3.0f)};
  // No cluster: every ray is exact, whatever it found.
  EXPECT_EQ(lev::visibility_noise(estimates, {1, 0, 1}, {}, {}), 0.0);
  // Clusters all seen, or all hidden: p is 1 or 0.
  EXPECT_EQ(lev::visibility_noise(estimates, {1, 1, 1}, {centred_at(0), centred_at(2)}, {1}), 0.0);
  EXPECT_EQ(lev::visibility_noise(estimates, {0, 0, 0}, {centred_at(0)}, {1, 2}), 0.0);
}

TEST(VisibilityNoise, IsTheBinomialDeviationOfTheClustersPooledVisibleShare) {
  // Two centred clusters of 1 and 3 (brightest channel), one exact of 4, a single light of 100
  // that is hidden and counts for nothing: the rays found 1 + 4 of 8 visible.
  const std::vector<glm::vec3> estimates = {glm::vec3(1.0f, 0.5f, 0.0f), glm::vec3(3.0f),
                                            glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(100.0f)};
  const std::vector<std::uint8_t> visible = {1, 0, 1, 0};
  const double p = 5.0 / 8.0;
  EXPECT_NEAR(lev::visibility_noise(estimates, visible, {centred_at(0), centred_at(1)}, {2}),
              std::sqrt(p * (1.0 - p) * (1.0 + 9.0 + 16.0)), 1e-12);
  // A dark cluster (no ray was cast) adds nothing.
  const std::vector<glm::vec3> with_dark = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(1.0f)};
  EXPECT_NEAR(lev::visibility_noise(with_dark, {1, 0, 0}, {centred_at(0), centred_at(1)}, {2}),
              std::sqrt(0.25 * 2.0), 1e-12);
}

}  // namespace
