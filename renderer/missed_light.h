// The missed light per pixel (lev/missed_light.h): each sample's estimate of what its method left
// out, with shadows, summed in Framebuffer::missed_sum through the path weights as the radiance
// is, so its mean over a pixel's samples estimates (rt's pixel - the method's pixel) before 8-bit
// rounding. Put on the error scale of pixel_error.h (per channel |value|, at most 1, summed over
// channels, of 3, in percent) it is comparable with the true error against rt, and its standard
// error (from the draws' variance) beside it says how far to trust it.
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/framebuffer.h"

namespace renderer {

struct MissedLightStats {
  double average_pct = 0.0;
  double max_pct = 0.0;
  double std_error_avg_pct = 0.0;  // the estimate's standard error, averaged over pixels
};

// Pixel i's estimate and its standard error in percent; 0 without samples or estimate.
double pixel_missed_pct(const Framebuffer& framebuffer, std::size_t i);
double pixel_missed_std_error_pct(const Framebuffer& framebuffer, std::size_t i);
// The same before the exposure, per channel (0 without samples or estimate), and their percent
// at an exposure: missed_pct(pixel_missed_mean(f, i), f.exposure_scale) is pixel_missed_pct,
// bit for bit, and so for the standard error.
glm::vec3 pixel_missed_mean(const Framebuffer& framebuffer, std::size_t i);
glm::vec3 pixel_missed_std_error(const Framebuffer& framebuffer, std::size_t i);
double missed_pct(const glm::vec3& missed_mean, float exposure_scale);
double missed_std_error_pct(const glm::vec3& missed_std_error, float exposure_scale);
// Every pixel's estimate in percent, in pixel order (the heatmap's).
std::vector<double> missed_pct_image(const Framebuffer& framebuffer);
// Over the pixels with a sample (those rendered_rgb8 keeps).
MissedLightStats missed_light_stats(const Framebuffer& framebuffer);

}  // namespace renderer
