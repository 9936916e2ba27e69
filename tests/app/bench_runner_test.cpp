// The bench runner's arithmetic: a subsampled render's time is scaled to the whole frame pass by
// pass, while its set-up (selector, extent volumes, the rt fallback's probe), which does not grow
// with the pixels, is counted once.
#include <cmath>

#include <gtest/gtest.h>

#include "app/bench/runner.h"

namespace {

TEST(BenchRunner, ASubsampledRenderScalesItsPassesToTheFrameAndCountsItsSetupOnce) {
  app::bench::Measurement m;
  m.pixels = 100;
  m.full_pixels = 1600;  // one pixel in 16
  m.cpu_seconds = 2.0;
  m.setup_cpu_seconds = 0.5;
  m.seconds = 1.25;
  m.setup_seconds = 0.25;
  EXPECT_DOUBLE_EQ(m.full_frame_cpu_seconds(), 0.5 + 1.5 * 16);
  EXPECT_DOUBLE_EQ(m.full_frame_seconds(), 0.25 + 1.0 * 16);

  m.full_pixels = 100;  // every pixel: the time itself
  EXPECT_DOUBLE_EQ(m.full_frame_cpu_seconds(), 2.0);
  EXPECT_DOUBLE_EQ(m.full_frame_seconds(), 1.25);

  m.pixels = 0;  // nothing rendered: no time to scale
  EXPECT_TRUE(std::isnan(m.full_frame_cpu_seconds()));
}

TEST(BenchRunner, AProgressiveRenderCountsItsSetupOnceBeforeItsScaledPasses) {
  app::bench::ProgressMeasurement m;
  m.pixels = 25;
  m.full_pixels = 100;
  m.setup_cpu_seconds = 0.3;
  m.setup_seconds = 0.2;
  app::bench::PassSnapshot s;
  s.cpu_seconds = 1.0;
  s.seconds = 0.5;
  EXPECT_DOUBLE_EQ(m.full_frame_cpu_seconds(s), 0.3 + 4.0);
  EXPECT_DOUBLE_EQ(m.full_frame_seconds(s), 0.2 + 2.0);
}

}  // namespace
