// What a render accumulates per pixel: the radiance of every sample, the sample count, and the
// work counters behind the heatmaps and statistics. Each pixel is written by one tile task at a
// time, so no locks are needed and sums never depend on thread interleaving.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace renderer {

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> radiance_sum;
  std::vector<std::uint32_t> samples;
  std::vector<std::uint64_t> shading_points;  // per pixel, summed over samples and bounces
  std::vector<std::uint64_t> lights_tested;
  std::vector<std::uint64_t> nodes_visited;
  std::vector<std::uint64_t> shadow_rays;
  // Per pixel, summed over samples: the certified bound of |radiance - rt's radiance| (RGB,
  // error_bound.h); zero unless RenderSettings::compute_error_bound.
  std::vector<glm::vec3> error_bound_sum;
  // Per pixel and channel, the sum of each sample's radiance squared: with radiance_sum and
  // samples, the variance across passes behind the noise estimate (pixel_noise.h). In double: a
  // sample may be as bright as the largest float / 2^17 (clamp_sample_radiance), whose square is
  // past the float range.
  std::vector<glm::dvec3> radiance_square_sum;
  // Per pixel, summed over samples, when the render estimates the missed light (empty when not):
  // the estimate (RGB radiance, renderer/missed_light.h) and its variance.
  std::vector<glm::vec3> missed_sum;
  std::vector<glm::vec3> missed_variance_sum;
  // 2^EV of the displayed units its error metrics are measured on (RenderSettings::exposure_ev):
  // framebuffer_rgb8, the error bound, the noise and the missed-light estimate all read the
  // radiance times this. 1 at EV 0.
  float exposure_scale = 1.0f;
};

Framebuffer make_framebuffer(int width, int height);
void clear_framebuffer(Framebuffer& framebuffer);
// Gives the framebuffer the missed-light sums (zero); clear_framebuffer keeps them.
void allocate_missed_light(Framebuffer& framebuffer);

// 8-bit RGB of the mean exposed radiance (radiance x exposure_scale) clamped to [0, 1] (1.0 =
// 255, the units of the tolerance): the linear image the pixel errors compare, and at EV 0 the
// image levrt writes for a scene at its linear default.
std::vector<std::uint8_t> framebuffer_rgb8(const Framebuffer& framebuffer);

struct FramebufferTotals {
  std::uint64_t samples = 0;
  std::uint64_t shading_points = 0;
  std::uint64_t lights_tested = 0;
  std::uint64_t nodes_visited = 0;
  std::uint64_t shadow_rays = 0;
  std::uint32_t lights_tested_max = 0;  // per shading point, over pixels (pixel mean)
  // The certified error bound (error_bound.h) of the pixels with a sample: how many they are,
  // the sum and the largest of their bounds, in percent of 765.
  std::uint64_t pixels_sampled = 0;
  double error_bound_pct_sum = 0.0;
  double error_bound_pct_max = 0.0;
};
// Adds pixel i's counters to totals (sum_framebuffer is this over every pixel).
void add_pixel_totals(const Framebuffer& framebuffer, std::size_t i, FramebufferTotals& totals);
FramebufferTotals sum_framebuffer(const Framebuffer& framebuffer);
// Adds the totals of other pixels (a tile's) to totals.
void add_totals(const FramebufferTotals& other, FramebufferTotals& totals);

}  // namespace renderer
