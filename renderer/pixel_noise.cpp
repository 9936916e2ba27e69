#include "renderer/pixel_noise.h"

#include <algorithm>
#include <cmath>

namespace renderer {
double pixel_std_error(const Framebuffer& f, std::size_t i) {
  if (f.samples[i] < 2) return 0.0;
  const double n = f.samples[i];
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double mean = static_cast<double>(f.radiance_sum[i][c]) / n;
    // Rounding may leave a constant pixel a tiny negative variance.
    const double variance =
        std::max(0.0, (f.radiance_square_sum[i][c] - n * mean * mean) / (n - 1.0));
    sum += std::sqrt(variance / n);
  }
  return sum;
}

double std_error_pct(double std_error, float exposure_scale) {
  // 1.0 = 255 after the exposure: a channel's error e is e * 255 / 765 of the scale, in percent.
  return std_error * static_cast<double>(exposure_scale) * 100.0 / 3.0;
}

double pixel_std_error_pct(const Framebuffer& f, std::size_t i) {
  return std_error_pct(pixel_std_error(f, i), f.exposure_scale);
}

std::vector<double> pixel_std_error_pct(const Framebuffer& f) {
  std::vector<double> out(f.samples.size(), 0.0);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = pixel_std_error_pct(f, i);
  return out;
}

double std_error_avg_pct(const Framebuffer& f) {
  double sum = 0.0;
  std::size_t pixels = 0;
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    if (f.samples[i] < 2) continue;
    sum += pixel_std_error_pct(f, i);
    ++pixels;
  }
  return pixels > 0 ? sum / static_cast<double>(pixels) : 0.0;
}

}  // namespace renderer
