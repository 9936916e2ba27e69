#include "renderer/display_transform.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace {

using renderer::DisplayCurve;

TEST(DisplayTransform, SrgbKnownValues) {
  EXPECT_FLOAT_EQ(renderer::srgb_encode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(renderer::srgb_encode(1.0f), 1.0f);
  EXPECT_NEAR(renderer::srgb_encode(0.0031308f), 0.040450f, 1e-5f);  // the two pieces meet
  EXPECT_NEAR(renderer::srgb_encode(0.5f), 0.735357f, 1e-5f);
  EXPECT_NEAR(renderer::srgb_encode(0.18f), 0.461356f, 1e-5f);
  EXPECT_FLOAT_EQ(renderer::srgb_encode(2.0f), 1.0f);
  EXPECT_FLOAT_EQ(renderer::srgb_encode(-1.0f), 0.0f);
}

TEST(DisplayTransform, PbrNeutralKnownValues) {
  // Below the compression start only the toe offset applies.
  EXPECT_NEAR(renderer::pbr_neutral(glm::vec3(0.5f)).x, 0.46f, 1e-6f);
  EXPECT_NEAR(renderer::pbr_neutral(glm::vec3(0.04f)).x, 0.04f - (0.04f - 6.25f * 0.04f * 0.04f),
              1e-6f);
  EXPECT_FLOAT_EQ(renderer::pbr_neutral(glm::vec3(0.0f)).x, 0.0f);
  // Grey 1.0: offset to 0.96, peak compressed to 1 - 0.24^2 / 0.44.
  EXPECT_NEAR(renderer::pbr_neutral(glm::vec3(1.0f)).x, 1.0f - 0.0576f / 0.44f, 1e-5f);
  // A saturated red above the knee: compressed and pulled towards grey, never above 1.
  const glm::vec3 red = renderer::pbr_neutral(glm::vec3(4.0f, 0.0f, 0.0f));
  const float peak = 4.0f, new_peak = 1.0f - 0.0576f / (peak + 0.24f - 0.76f);
  const float g = 1.0f - 1.0f / (0.15f * (peak - new_peak) + 1.0f);
  EXPECT_NEAR(red.x, new_peak, 1e-5f);
  EXPECT_NEAR(red.y, new_peak * g, 1e-5f);
  EXPECT_LT(renderer::pbr_neutral(glm::vec3(1e6f)).x, 1.0f);
}

TEST(DisplayTransform, CurvesThroughTheExposure) {
  const glm::vec3 radiance(0.25f, 0.5f, 2.0f);
  const glm::vec3 linear = renderer::display_colour(radiance, 2.0f, DisplayCurve::linear);
  EXPECT_FLOAT_EQ(linear.x, 0.5f);
  EXPECT_FLOAT_EQ(linear.y, 1.0f);
  EXPECT_FLOAT_EQ(linear.z, 1.0f);
  const glm::vec3 srgb = renderer::display_colour(radiance, 2.0f, DisplayCurve::srgb);
  EXPECT_NEAR(srgb.x, 0.735357f, 1e-5f);
  const glm::vec3 neutral = renderer::display_colour(glm::vec3(0.25f), 2.0f, DisplayCurve::neutral);
  EXPECT_NEAR(neutral.x, renderer::srgb_encode(0.46f), 1e-5f);
  std::uint8_t rgb[3];
  renderer::display_rgb8(glm::vec3(0.25f), 2.0f, DisplayCurve::srgb, rgb);
  EXPECT_EQ(rgb[0], 188);  // 0.735357 x 255 = 187.5 rounds up
  EXPECT_FLOAT_EQ(renderer::exposure_scale(0.0), 1.0f);
  EXPECT_FLOAT_EQ(renderer::exposure_scale(-2.0), 0.25f);
}

// The display step at linear, EV 0 is framebuffer_rgb8, bit for bit, whatever the radiance:
// negative, above 1, NaN, infinite, and pixels without a sample.
TEST(DisplayTransform, LinearAtExposureZeroIsTheUndisplayedImage) {
  renderer::Framebuffer f = renderer::make_framebuffer(7, 5);
  const float values[] = {-1.0f, 0.0f,  1e-4f, 0.00196f, 0.5f,      0.99804f,   1.0f,
                          1.5f,  1e30f, NAN,   INFINITY, -INFINITY, 0.1234567f, 0.7777f};
  for (std::size_t i = 0; i < f.radiance_sum.size(); ++i) {
    const std::size_t n = std::size(values);
    f.radiance_sum[i] = glm::vec3(values[i % n], values[(3 * i + 1) % n], values[(5 * i + 2) % n]);
    f.samples[i] = static_cast<std::uint32_t>(i % 4);  // some pixels have no sample
    f.radiance_sum[i] *= static_cast<float>(f.samples[i]);
  }
  EXPECT_EQ(renderer::display_framebuffer_rgb8(f, {0.0, DisplayCurve::linear}),
            renderer::framebuffer_rgb8(f));
}

TEST(DisplayTransform, CurveNamesRoundTrip) {
  for (const std::string& name : renderer::display_curve_names()) {
    ASSERT_TRUE(renderer::parse_display_curve(name));
    EXPECT_EQ(renderer::display_curve_name(*renderer::parse_display_curve(name)), name);
  }
  EXPECT_FALSE(renderer::parse_display_curve("aces"));
}

TEST(DisplayTransform, ExposedGreyInvertsTheCurve) {
  for (DisplayCurve c : {DisplayCurve::linear, DisplayCurve::srgb, DisplayCurve::neutral}) {
    const float grey = renderer::exposed_grey_for_display(0.75f, c);
    EXPECT_NEAR(renderer::display_colour(glm::vec3(grey), 1.0f, c).x, 0.75f, 1e-5f);
  }
  EXPECT_NEAR(renderer::exposed_grey_for_display(0.75f, DisplayCurve::linear), 0.75f, 1e-6f);
}

}  // namespace
