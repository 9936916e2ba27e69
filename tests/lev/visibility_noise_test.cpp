// visibility_noise: the binomial noise of a cut's 0/1 shadow rays over its clusters of several
// lights, sqrt(p (1 - p) sum u^2) with p the visible share the rays found, pooled; single lights
// carry none.
#include "lev/visibility_noise.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace {

TEST(VisibilityNoise, LightsAloneAndClustersAllSeenOrAllHiddenAreExact) {
  const std::vector<glm::vec3> estimates = {glm::vec3(1.0f), glm::vec3(2.0f), glm::vec3(3.0f)};
  // No cluster: every ray is exact, whatever it found.
  EXPECT_EQ(lev::visibility_noise(estimates, {1, 0, 1}, {}), 0.0);
  // Clusters all seen, or all hidden: p is 1 or 0.
  EXPECT_EQ(lev::visibility_noise(estimates, {1, 1, 1}, {0, 1, 2}), 0.0);
  EXPECT_EQ(lev::visibility_noise(estimates, {0, 0, 0}, {0, 1, 2}), 0.0);
}

TEST(VisibilityNoise, IsTheBinomialDeviationOfTheClustersPooledVisibleShare) {
  // Clusters of 1, 3 and 4 (brightest channel), a single light of 100 that is hidden and counts
  // for nothing: the rays found 1 + 4 of 8 visible.
  const std::vector<glm::vec3> estimates = {glm::vec3(1.0f, 0.5f, 0.0f), glm::vec3(3.0f),
                                            glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(100.0f)};
  const std::vector<std::uint8_t> visible = {1, 0, 1, 0};
  const double p = 5.0 / 8.0;
  EXPECT_NEAR(lev::visibility_noise(estimates, visible, {0, 1, 2}),
              std::sqrt(p * (1.0 - p) * (1.0 + 9.0 + 16.0)), 1e-12);
  // A dark cluster (no ray was cast) adds nothing.
  const std::vector<glm::vec3> with_dark = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(1.0f)};
  EXPECT_NEAR(lev::visibility_noise(with_dark, {1, 0, 0}, {0, 1, 2}), std::sqrt(0.25 * 2.0), 1e-12);
  // An infinite estimate gives no finite noise: NaN, which never refines (a comparison fails).
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(lev::visibility_noise({glm::vec3(inf), glm::vec3(1.0f)}, {1, 0}, {0, 1}) > 0.0);
}

}  // namespace
