#include "renderer/missed_light.h"

#include <algorithm>
#include <cmath>

#include "renderer/error_bound.h"

namespace renderer {

glm::vec3 pixel_missed_mean(const Framebuffer& f, std::size_t i) {
  if (f.missed_sum.empty() || f.samples[i] == 0) return glm::vec3(0.0f);
  return f.missed_sum[i] / static_cast<float>(f.samples[i]);
}

glm::vec3 pixel_missed_std_error(const Framebuffer& f, std::size_t i) {
  if (f.missed_variance_sum.empty() || f.samples[i] == 0) return glm::vec3(0.0f);
  // The mean of n independent samples: the variances summed, over n^2.
  return glm::sqrt(f.missed_variance_sum[i]) / static_cast<float>(f.samples[i]);
}

double missed_pct(const glm::vec3& missed_mean, float exposure_scale) {
  // The error scale's arithmetic is the bound's: |value| per channel, clamped at 1.
  return error_bound_pct(glm::abs(missed_mean * exposure_scale));
}

double missed_std_error_pct(const glm::vec3& missed_std_error, float exposure_scale) {
  return error_bound_pct(missed_std_error * exposure_scale);
}

double pixel_missed_pct(const Framebuffer& f, std::size_t i) {
  if (f.missed_sum.empty() || f.samples[i] == 0) return 0.0;
  return missed_pct(pixel_missed_mean(f, i), f.exposure_scale);
}

double pixel_missed_std_error_pct(const Framebuffer& f, std::size_t i) {
  if (f.missed_variance_sum.empty() || f.samples[i] == 0) return 0.0;
  return missed_std_error_pct(pixel_missed_std_error(f, i), f.exposure_scale);
}

std::vector<double> missed_pct_image(const Framebuffer& f) {
  std::vector<double> pct(f.samples.size());
  for (std::size_t i = 0; i < pct.size(); ++i) pct[i] = pixel_missed_pct(f, i);
  return pct;
}

MissedLightStats missed_light_stats(const Framebuffer& f) {
  MissedLightStats s;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    if (f.samples[i] == 0) continue;
    const double pct = pixel_missed_pct(f, i);
    ++pixels;
    s.average_pct += pct;
    s.max_pct = std::max(s.max_pct, pct);
    s.std_error_avg_pct += pixel_missed_std_error_pct(f, i);
  }
  if (pixels > 0) {
    s.average_pct /= static_cast<double>(pixels);
    s.std_error_avg_pct /= static_cast<double>(pixels);
  }
  return s;
}

}  // namespace renderer
