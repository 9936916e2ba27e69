#include "lev/placed_light_memo.h"

#include <gtest/gtest.h>

#include <vector>

#include "lev/light.h"

namespace {

lev::Light memo_test_light(float x) {
  return lev::make_point_light({x, 0.0f, 0.0f}, glm::vec3(1.0f));
}

// A light is made once per node and frame, found again for the same bits, and made anew for a
// frame that differs in one bit (-0 against +0) or another node.
TEST(PlacedLightMemo, MakesEachPlacedSubtreesLightOnceAndFindsItForTheSameBits) {
  lev::PlacedLightMemo memo;
  memo.serve(&memo, nullptr);
  int made = 0;
  const auto make = [&](float x) {
    return [&made, x] {
      ++made;
      return memo_test_light(x);
    };
  };
  const glm::mat3 turn(1.0f);
  EXPECT_EQ(memo.find_or_make(7, turn, 1.0f, {0.0f, 1.0f, 2.0f}, make(1.0f)).position.x, 1.0f);
  EXPECT_EQ(memo.find_or_make(7, turn, 1.0f, {0.0f, 1.0f, 2.0f}, make(9.0f)).position.x, 1.0f);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(memo.find_or_make(7, turn, 1.0f, {-0.0f, 1.0f, 2.0f}, make(2.0f)).position.x, 2.0f);
  EXPECT_EQ(memo.find_or_make(8, turn, 1.0f, {0.0f, 1.0f, 2.0f}, make(3.0f)).position.x, 3.0f);
  EXPECT_EQ(memo.find_or_make(7, turn, 2.0f, {0.0f, 1.0f, 2.0f}, make(4.0f)).position.x, 4.0f);
  EXPECT_EQ(made, 4);
}

// Serving another hierarchy forgets every light made for the last one; serving the same one
// again keeps them.
TEST(PlacedLightMemo, ServingAnotherHierarchyForgetsWhatWasMade) {
  lev::PlacedLightMemo memo;
  int first = 0, second = 0;
  memo.serve(&first, nullptr);
  const glm::mat3 turn(1.0f);
  memo.find_or_make(3, turn, 1.0f, glm::vec3(0.0f), [] { return memo_test_light(1.0f); });
  memo.serve(&first, nullptr);
  EXPECT_EQ(memo.find_or_make(3, turn, 1.0f, glm::vec3(0.0f), [] { return memo_test_light(5.0f); })
                .position.x,
            1.0f);
  memo.serve(&second, nullptr);
  EXPECT_EQ(memo.find_or_make(3, turn, 1.0f, glm::vec3(0.0f), [] { return memo_test_light(6.0f); })
                .position.x,
            6.0f);
}

// More subtrees than entries: every answer is still the light made for its own key, whatever
// the order they are asked in.
TEST(PlacedLightMemo, CollidingSubtreesGetTheirOwnLights) {
  lev::PlacedLightMemo memo;
  memo.serve(&memo, nullptr);
  const glm::mat3 turn(1.0f);
  const std::uint32_t count = 3 * lev::PlacedLightMemo::kEntries;
  for (int round = 0; round < 2; ++round) {
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t node = round == 0 ? k : count - 1 - k;
      const float x = static_cast<float>(node);
      ASSERT_EQ(memo.find_or_make(node, turn, 1.0f, glm::vec3(0.5f * x),
                                  [x] { return memo_test_light(x); })
                    .position.x,
                x)
          << node;
    }
  }
}

}  // namespace
