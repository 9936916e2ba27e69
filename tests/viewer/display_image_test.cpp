// The UI's copy of a render at another exposure (app/viewer/display_image.h): a render that goes
// on when the exposure changes (rt, the samplers, lightcuts) is shown at the new exposure with
// the colours and figures a render at that exposure reports, bit for bit, and the tiles it
// still sends at the old one are shown at the new one too.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "app/viewer/display_buffer.h"
#include "app/viewer/display_image.h"
#include "renderer/error_bound.h"
#include "renderer/framebuffer.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_noise.h"

namespace {

using app::viewer::DisplayImage;

// `samples` passes of a 9 x 7 render at the given exposure, with the missed-light estimate:
// radiance, spread, bound and estimate vary from pixel to pixel, and many of them pass 1.0 once
// exposed at 4x, so the clamps of the 8-bit colour and of the error scale are exercised.
renderer::Framebuffer render_at(float exposure_scale, std::uint32_t samples) {
  renderer::Framebuffer f = renderer::make_framebuffer(9, 7);
  renderer::allocate_missed_light(f);
  f.exposure_scale = exposure_scale;
  const auto n = static_cast<float>(samples);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    const float t = static_cast<float>(i % 11) / 10.0f;
    const glm::vec3 mean(0.6f * t, 0.3f * (1.0f - t), 0.45f);
    f.samples[i] = i % 13 == 0 ? 0 : samples;  // some pixels skipped (a subsample)
    if (f.samples[i] == 0) continue;
    f.radiance_sum[i] = mean * n;
    f.radiance_square_sum[i] = n * mean * mean + glm::vec3(n * 0.0004f * t);
    f.error_bound_sum[i] = glm::vec3(0.2f * t, 0.05f, 0.4f * (1.0f - t)) * n;
    f.missed_sum[i] = glm::vec3(0.3f * t - 0.1f, 0.02f, 0.0f) * n;
    f.missed_variance_sum[i] = glm::vec3(0.001f * t, 0.0f, 0.002f);
  }
  return f;
}

app::viewer::TileUpdate whole_frame(const renderer::Framebuffer& f, int pass) {
  return app::viewer::copy_tile(f, 5, 0, pass, {0, 0, f.width, f.height});
}

// Every exposure-dependent field of the two images, equal bit for bit.
void expect_same_figures(const DisplayImage& a, const DisplayImage& b) {
  EXPECT_EQ(a.exposure_scale, b.exposure_scale);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.error_bound_pct, b.error_bound_pct);
  EXPECT_EQ(a.noise_pct, b.noise_pct);
  EXPECT_EQ(a.missed_pct, b.missed_pct);
  EXPECT_EQ(a.missed_std_error_pct, b.missed_std_error_pct);
}

TEST(DisplayImage, ATileIsShownAtItsRendersExposureAsTheRendererReportsIt) {
  const renderer::Framebuffer f = render_at(4.0f, 3);
  DisplayImage image;
  app::viewer::apply_tile_updates(image, {whole_frame(f, 2)});
  EXPECT_EQ(image.exposure_scale, 4.0f);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    std::uint8_t rgb[3];
    app::viewer::mean_rgb8(f, i, rgb);
    if (f.samples[i] > 0) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(image.rgb[3 * i + c], rgb[c]) << i;
    }
    EXPECT_EQ(image.error_bound_pct[i], static_cast<float>(renderer::pixel_error_bound_pct(f, i)))
        << i;
    EXPECT_EQ(image.noise_pct[i], static_cast<float>(renderer::pixel_std_error_pct(f, i))) << i;
    EXPECT_EQ(image.missed_pct[i], static_cast<float>(renderer::pixel_missed_pct(f, i))) << i;
    EXPECT_EQ(image.missed_std_error_pct[i],
              static_cast<float>(renderer::pixel_missed_std_error_pct(f, i)))
        << i;
  }
}

TEST(DisplayImage, ReExposedItEqualsTheRenderAtTheNewExposure) {
  for (const float shown : {4.0f, 0.25f}) {
    DisplayImage re_exposed;
    app::viewer::apply_tile_updates(re_exposed, {whole_frame(render_at(1.0f, 2), 1)});
    const std::vector<std::uint8_t> before = re_exposed.rgb;
    const std::uint64_t version = re_exposed.version;
    EXPECT_TRUE(app::viewer::expose_display_image(re_exposed, shown));
    EXPECT_GT(re_exposed.version, version);
    EXPECT_NE(re_exposed.rgb, before) << shown;  // the check can fail
    DisplayImage rendered;
    app::viewer::apply_tile_updates(rendered, {whole_frame(render_at(shown, 2), 1)});
    expect_same_figures(re_exposed, rendered);
    EXPECT_FALSE(app::viewer::expose_display_image(re_exposed, shown));  // nothing new

    // The render goes on at its own exposure: its next pass is shown at the exposure shown.
    app::viewer::apply_tile_updates(re_exposed, {whole_frame(render_at(1.0f, 3), 2)});
    app::viewer::apply_tile_updates(rendered, {whole_frame(render_at(shown, 3), 2)});
    expect_same_figures(re_exposed, rendered);
  }
}

}  // namespace
