// The image's group of the settings (renderer::ImageSettings) compares every member.
#include <gtest/gtest.h>

#include "renderer/render.h"

namespace {

TEST(ImageSettings, EveryMemberIsCompared) {
  const renderer::ImageSettings a;
  EXPECT_EQ(a, a);
  void (*const changes[])(renderer::ImageSettings&) = {
      [](renderer::ImageSettings& s) { s.width += 1; },
      [](renderer::ImageSettings& s) { s.height += 1; },
      [](renderer::ImageSettings& s) { s.spp += 1; },
      [](renderer::ImageSettings& s) { s.depth += 1; },
      [](renderer::ImageSettings& s) { s.subsample += 1; },
      [](renderer::ImageSettings& s) { s.threads += 1; },
      [](renderer::ImageSettings& s) { s.missed_draws += 2; },
  };
  for (const auto& change : changes) {
    renderer::ImageSettings b = a;
    change(b);
    EXPECT_NE(a, b);
    EXPECT_FALSE(a == b);
  }
}

}  // namespace
