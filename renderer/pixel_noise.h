// The noise of a progressive render, estimated from the framebuffer alone: per pixel the standard
// error of the mean over its samples (the sample variance across passes over the sample count,
// square-rooted), per channel, summed over the channels and put on the pixel error scale of
// docs/design.md (|dR|+|dG|+|dB| on 0..255, over 765, in percent). For an unbiased method it
// estimates how far the image still is from the one its passes converge to; it also counts the
// antialiasing jitter, which the rt reference of the same passes shares, so it is an upper
// estimate of the error against that reference.
#pragma once

#include <vector>

#include "renderer/framebuffer.h"

namespace renderer {

// One pixel, in percent; 0 for a pixel with fewer than two samples (no variance known).
double pixel_std_error_pct(const Framebuffer& framebuffer, std::size_t pixel);
// The same before the exposure: the channels' standard errors of the scene-linear mean, summed.
// It and std_error_pct give pixel_std_error_pct at any exposure, bit for bit (the viewer's image
// at an exposure its render was not made at).
double pixel_std_error(const Framebuffer& framebuffer, std::size_t pixel);
double std_error_pct(double std_error, float exposure_scale);
// Every pixel, as above.
std::vector<double> pixel_std_error_pct(const Framebuffer& framebuffer);

// The average of pixel_std_error_pct over the pixels with at least two samples; 0 when none has.
double std_error_avg_pct(const Framebuffer& framebuffer);

}  // namespace renderer
