// The shading loop rt and lev share (sum_visible_lights): a million small contributions must sum
// as accurately as a double reference, and in a fixed order so that images are deterministic.
#include "lev/light_selector.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>

#include <gtest/gtest.h>

namespace {

constexpr std::size_t kManyLights = std::size_t{1} << 20;

// The same light, n times over, without storing n copies.
class RepeatedLight {
 public:
  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = lev::Light;
    using difference_type = std::ptrdiff_t;
    using pointer = const lev::Light*;
    using reference = const lev::Light&;
    Iterator(const lev::Light& light, std::size_t index) : light_(&light), index_(index) {}
    const lev::Light& operator*() const { return *light_; }
    Iterator& operator++() {
      ++index_;
      return *this;
    }
    bool operator!=(const Iterator& other) const { return index_ != other.index_; }

   private:
    const lev::Light* light_;
    std::size_t index_;
  };

  RepeatedLight(const lev::Light& light, std::size_t count) : light_(light), count_(count) {}
  Iterator begin() const { return {light_, 0}; }
  Iterator end() const { return {light_, count_}; }

 private:
  lev::Light light_;
  std::size_t count_;
};

// Every light adds the same small radiance and none is shadowed.
class ConstantPoint final : public lev::ShadingPoint {
 public:
  explicit ConstantPoint(const glm::vec3& radiance) : radiance_(radiance) {}
  glm::vec3 position() const override { return glm::vec3(0.0f); }
  glm::vec3 unshadowed_radiance(const lev::Light&) const override { return radiance_; }
  bool visible(const lev::Light&) override { return true; }

 private:
  glm::vec3 radiance_;
};

TEST(SumVisibleLights, MillionSmallContributionsMatchADoubleReference) {
  // Not powers of two, so a float running sum rounds at nearly every step: summed in float,
  // these drift by 0.3% to 1% (computed: 1e-6 gives 0.65%, 1e-3 0.95%).
  const glm::vec3 radiance(1e-6f, 3e-7f, 1e-3f);
  ConstantPoint point(radiance);
  lev::SelectionCounters counters;
  const glm::vec3 sum = lev::sum_visible_lights(
      RepeatedLight(lev::make_point_light(glm::vec3(1.0f), glm::vec3(1.0f)), kManyLights),
      [](const lev::Light&) { return true; }, point, counters);
  EXPECT_EQ(counters.lights_tested, kManyLights);
  EXPECT_EQ(counters.shadow_rays, kManyLights);
  for (int c = 0; c < 3; ++c) {
    const double reference = static_cast<double>(radiance[c]) * static_cast<double>(kManyLights);
    EXPECT_NEAR(sum[c], reference, 1e-5 * reference) << "channel " << c;
  }
}

// The float running sum the loop used to keep really is that far off: the test above would
// catch a return to it.
TEST(SumVisibleLights, FloatRunningSumOfTheSameTermsDrifts) {
  const float term = 1e-6f;
  float running = 0.0f;
  for (std::size_t i = 0; i < kManyLights; ++i) running += term;
  const double reference = static_cast<double>(term) * static_cast<double>(kManyLights);
  EXPECT_GT(std::abs(static_cast<double>(running) - reference), 1e-3 * reference);
}

TEST(SumVisibleLights, SkipsUnselectedLightsAndIsRepeatable) {
  ConstantPoint point(glm::vec3(0.1f, 0.2f, 0.3f));
  std::uint64_t seen = 0;
  // Every third light is selected.
  const auto every_third = [&seen](const lev::Light&) { return seen++ % 3 == 0; };
  const RepeatedLight lights(lev::make_point_light(glm::vec3(0.0f), glm::vec3(1.0f)), 3000);
  lev::SelectionCounters first_counters, second_counters;
  const glm::vec3 first = lev::sum_visible_lights(lights, every_third, point, first_counters);
  seen = 0;
  const glm::vec3 second = lev::sum_visible_lights(lights, every_third, point, second_counters);
  EXPECT_EQ(first_counters.lights_tested, 1000u);
  EXPECT_EQ(first, second);
  EXPECT_NEAR(first.z, 300.0f, 300.0f * 1e-6f);
}

}  // namespace
