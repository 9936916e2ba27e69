// The missed-light estimate (lev/missed_light.h) at the selectors: for lev, lev_est and
// lev_bounded its mean over many random streams matches rt's direct radiance minus the method's
// (with shadows: a point whose visibility is a fixed function of the light); it reads exactly 0
// where every culled light is occluded; asking for it changes neither the method's radiance nor
// its counters, and the same stream gives the same estimate.
#include "lev/missed_light.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/light_hierarchy.h"
#include "lev/methods.h"
#include "tests/lev/random_light_scenes.h"

namespace {

using lev_test::Random;

// A surface facing every light that reflects irradiance unchanged, with shadows: a light is
// hidden when `hide_all`, or when its position's x is negative (a fixed wall along x = 0).
class ShadowedPoint final : public lev::ShadingPoint {
 public:
  ShadowedPoint(const glm::vec3& x, bool hide_all) : x_(x), hide_all_(hide_all) {}
  glm::vec3 position() const override { return x_; }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    return lev::irradiance(light, x_);
  }
  bool visible(const lev::Light& light) override { return !hide_all_ && light.position.x >= 0.0f; }

 private:
  glm::vec3 x_;
  bool hide_all_;
};

struct Estimate {
  glm::dvec3 mean{0.0};
  glm::dvec3 variance_of_mean{0.0};  // of `mean`, from the estimates' own variances
};

// The missed light of `method` at the point, averaged over `streams` random streams.
Estimate mean_missed(const lev::LightSelector& selector, lev::ShadingPoint& point, int samples,
                     int streams) {
  Estimate e;
  lev::SelectorScratch scratch;
  for (int s = 0; s < streams; ++s) {
    lev::RandomStream random{0x51ED5EEDull + static_cast<std::uint64_t>(s)};
    lev::MissedLight missed;
    missed.draws = samples;
    missed.random = &random;
    scratch.missed = &missed;
    lev::SelectionCounters counters;
    selector.direct_radiance(point, scratch, counters);
    scratch.missed = nullptr;
    EXPECT_TRUE(missed.estimated);
    e.mean += glm::dvec3(missed.radiance);
    e.variance_of_mean += glm::dvec3(missed.variance);
  }
  e.mean /= streams;
  e.variance_of_mean /= static_cast<double>(streams) * streams;
  return e;
}

glm::vec3 direct(const lev::LightSelector& selector, lev::ShadingPoint& point) {
  lev::SelectorScratch scratch;
  lev::SelectionCounters counters;
  return selector.direct_radiance(point, scratch, counters);
}

const lev::Method kLeavingOut[] = {lev::Method::lev, lev::Method::lev_est,
                                   lev::Method::lev_bounded};

TEST(MissedLight, ItsMeanIsRtMinusTheMethodWithShadows) {
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Random r(seed);
    const lev::LightDescription tree = lev_test::random_instanced_tree(r);
    const lev::LightHierarchy h = lev::build_hierarchy(tree);
    const auto rt = lev::make_selector(h, {lev::Method::rt, 0.0f});
    for (const float tau : {0.01f, 0.1f}) {
      for (const lev::Method method : kLeavingOut) {
        const auto selector = lev::make_selector(h, {method, tau});
        for (int k = 0; k < 4; ++k) {
          const glm::vec3 x(r.uniform(-25, 25), r.uniform(-25, 25), r.uniform(-8, 8));
          ShadowedPoint point(x, false);
          const glm::dvec3 all(direct(*rt, point));
          const glm::dvec3 lost = all - glm::dvec3(direct(*selector, point));
          const Estimate e = mean_missed(*selector, point, 4, 400);
          const std::string context = std::string(lev::method_info(method).name) + " seed " +
                                      std::to_string(seed) + " tau " + std::to_string(tau);
          for (int c = 0; c < 3; ++c) {
            // Five standard errors, and room for the float rounding of the two direct sums (and
            // for lights of ~1e-7 at a spot cone's edge, which the importance may not reach).
            const double allowed = 5.0 * std::sqrt(e.variance_of_mean[c]) +
                                   1e-5 * (std::abs(all[c]) + std::abs(e.mean[c])) + 1e-6;
            EXPECT_NEAR(e.mean[c], lost[c], allowed) << context << " channel " << c;
          }
          if (lost.x > 1e-6) ++compared;
        }
      }
    }
  }
  // The check met points that really lost light.
  EXPECT_GT(compared, 20);
}

TEST(MissedLight, ReadsZeroWhereEveryCulledLightIsOccluded) {
  Random r(3);
  const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
  for (const lev::Method method : kLeavingOut) {
    const auto selector = lev::make_selector(h, {method, 0.05f});
    for (int k = 0; k < 20; ++k) {
      ShadowedPoint point({r.uniform(-25, 25), r.uniform(-25, 25), r.uniform(-8, 8)}, true);
      const Estimate e = mean_missed(*selector, point, 16, 1);
      // lev_est's clusters are hidden too, so nothing stands in either.
      EXPECT_EQ(e.mean, glm::dvec3(0.0)) << lev::method_info(method).name;
      EXPECT_EQ(e.variance_of_mean, glm::dvec3(0.0));
    }
  }
}

TEST(MissedLight, AskingChangesNothingOfTheMethodAndRepeatsForTheSameStream) {
  Random r(5);
  const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
  for (const lev::Method method : kLeavingOut) {
    const auto selector = lev::make_selector(h, {method, 0.01f});
    for (int k = 0; k < 20; ++k) {
      ShadowedPoint point({r.uniform(-25, 25), r.uniform(-25, 25), r.uniform(-8, 8)}, false);
      lev::SelectorScratch scratch;
      lev::SelectionCounters plain, asked;
      const glm::vec3 without = selector->direct_radiance(point, scratch, plain);
      glm::vec3 estimates[2];
      for (glm::vec3& estimate : estimates) {
        lev::RandomStream random{77};
        lev::MissedLight missed;
        missed.draws = 8;
        missed.random = &random;
        scratch.missed = &missed;
        asked = {};
        EXPECT_EQ(selector->direct_radiance(point, scratch, asked), without);
        scratch.missed = nullptr;
        estimate = missed.radiance;
      }
      EXPECT_EQ(asked.lights_tested, plain.lights_tested);
      EXPECT_EQ(asked.shadow_rays, plain.shadow_rays);
      EXPECT_EQ(asked.nodes_visited, plain.nodes_visited);
      EXPECT_EQ(estimates[0], estimates[1]);
    }
  }
}

TEST(MissedLight, RtAndTheSamplingMethodsLeaveItUnestimated) {
  Random r(7);
  const lev::LightHierarchy h = lev::build_hierarchy(lev_test::random_instanced_tree(r));
  for (const lev::Method method : {lev::Method::rt, lev::Method::lev_mc, lev::Method::light_tree}) {
    const auto selector = lev::make_selector(h, {method, 0.01f});
    ShadowedPoint point({1.0f, 2.0f, 3.0f}, false);
    lev::SelectorScratch scratch;
    lev::SelectionCounters counters;
    lev::RandomStream random{1};
    lev::MissedLight missed;
    missed.draws = 4;
    missed.random = &random;
    scratch.missed = &missed;
    selector->direct_radiance(point, scratch, counters);
    EXPECT_FALSE(missed.estimated) << lev::method_info(method).name;
  }
}

}  // namespace
