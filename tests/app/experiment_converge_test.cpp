// The converge experiment's snapshot schedule: half-octave steps, so that the error read at a
// time budget moves by at most 2^(1/4) with the noise of a method's time, not by sqrt(2).
#include <vector>

#include <gtest/gtest.h>

#include "app/bench/experiment_support.h"

namespace {

TEST(ConvergeSnapshots, HalfOctaveStepsUpToTheLastPass) {
  using app::bench::snapshot_pass_counts;
  EXPECT_EQ(snapshot_pass_counts(1), (std::vector<int>{1}));
  EXPECT_EQ(snapshot_pass_counts(3), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(snapshot_pass_counts(8), (std::vector<int>{1, 2, 3, 4, 6, 8}));
  const std::vector<int> full = snapshot_pass_counts(256);
  EXPECT_EQ(full.size(), 16u);
  EXPECT_EQ(full.back(), 256);
  for (std::size_t i = 1; i < full.size(); ++i) EXPECT_GT(full[i], full[i - 1]);
  // Past 1 -> 2, no step is more than 1.5x.
  for (std::size_t i = 2; i < full.size(); ++i)
    EXPECT_LE(2 * full[i], 3 * full[i - 1]) << "a step of more than 1.5x at " << full[i];
}

}  // namespace
