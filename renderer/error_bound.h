// The certified error bound (docs/design.md, "Methods"): how far a pixel of any method can be
// from the `rt` pixel of the same view. Every selector reports, per shading point, an upper bound
// of the unshadowed irradiance of the lights it neither shadow-tested nor accounted for
// (LightSelector::direct_radiance); the shading recursion (shading.cpp) turns it into radiance
// through the material's largest Phong response and weighs it by the path weight (the product of
// kr and kt) exactly as the radiance is weighed, so a sample's bound is at least
// |sample - rt sample| per channel. Ambient, suns and the recursion's cut-off are the same for
// every method, so they add nothing. A pixel's bound is the mean over its samples, put on the
// error scale of docs/design.md ("Metrics") like pixel_error.h's error: a clamped 8-bit channel
// cannot differ by more than 255, and rounding to 8 bits adds at most one step per channel on top
// of the bound.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "lev/important_lights.h"
#include "renderer/framebuffer.h"
#include "renderer/material.h"
#include "renderer/pixel_error.h"

namespace renderer {

// The largest Phong response (thesis eq. 6 without the irradiance) of the material to light from
// any direction toward any viewer: kd * colour + ks, since cos(theta) <= 1 and cos(alpha)^n <= 1
// (shading.cpp's response()). Absolute values, so a negative coefficient cannot shrink it.
glm::vec3 largest_response(const Material& material);

// Upper bound of the radiance error at one shading point whose selector left a culled
// irradiance bound (RGB): the bound times the largest response. A channel the material does not
// reflect at all bounds nothing, even when the irradiance bound is infinite (never inf * 0).
glm::vec3 shading_error_bound(const Material& material, const glm::vec3& culled_irradiance_bound);
// The same, with the selector's bound of the radiance error at the surface itself when it gave
// one (CulledRadianceBound: lev, lev_est, lev_cut, ast, lightcuts): per channel the smaller of
// the two, both upper bounds of the same error. The radiance bound counts each culled part's
// place around the surface (behind it, grazing, outside a narrow specular lobe), which the
// largest response cannot.
glm::vec3 shading_error_bound(const Material& material, const glm::vec3& culled_irradiance_bound,
                              const lev::CulledRadianceBound& culled_radiance);

// A pixel's bound on the error scale (docs/design.md, "Metrics"): sum over channels of
// min(bound_c, 1) * 255, as a percentage of 765. mean_bound is the pixel's bound per sample
// (Framebuffer::error_bound_sum over its samples).
double error_bound_pct(const glm::vec3& mean_bound);
// Pixel i's bound in percent; 0 for a pixel without samples.
double pixel_error_bound_pct(const Framebuffer& framebuffer, std::size_t i);
// Pixel i's mean bound per channel before the exposure (0 without samples):
// error_bound_pct(mean * exposure_scale) is pixel_error_bound_pct at that exposure, bit for bit.
glm::vec3 pixel_error_bound_mean(const Framebuffer& framebuffer, std::size_t i);
// Every pixel's bound in percent, in pixel order (0 where no sample was taken): the heatmap's.
std::vector<double> error_bound_pct_image(const Framebuffer& framebuffer);
// The bounds of the pixels with at least one sample, in pixel order: one per pixel of
// rendered_rgb8 (render_service.h), so a subsampled render's bounds line up with its pixels.
std::vector<double> rendered_error_bound_pct(const Framebuffer& framebuffer);

// One 8-bit step per channel on the error scale: the rounding of the two images compared, which
// the bound (on unrounded radiance) leaves out.
inline constexpr double kErrorBoundRoundingPct = 100.0 * 3.0 / 765.0;
// Whether a pixel's error against rt (pixel_error.h) is within its bound, rounding allowed.
bool within_error_bound(double error_pct, double bound_pct);

// Average and maximum bound over the pixels with at least one sample (the totals of a whole
// framebuffer or of the tiles received): the pixels rendered_rgb8 keeps, so the bound and the
// pixel error describe one set of pixels.
PixelErrorStats error_bound_stats(const FramebufferTotals& totals);

}  // namespace renderer
