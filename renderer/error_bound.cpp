#include "renderer/error_bound.h"

#include <algorithm>
#include <cmath>

#include "lev/light_bounds.h"

namespace renderer {

glm::vec3 largest_response(const Material& material) {
  lev::SurfaceResponse surface;
  surface.diffuse = material.kd * material.colour;
  surface.specular = material.ks;
  return lev::largest_response(surface);
}

glm::vec3 shading_error_bound(const Material& material, const glm::vec3& culled_irradiance_bound) {
  const glm::vec3 response = largest_response(material);
  glm::vec3 bound(0.0f);
  for (int c = 0; c < 3; ++c) {
    if (response[c] > 0.0f) bound[c] = response[c] * culled_irradiance_bound[c];
  }
  return bound;
}

glm::vec3 shading_error_bound(const Material& material, const glm::vec3& culled_irradiance_bound,
                              const lev::CulledRadianceBound& culled_radiance) {
  glm::vec3 bound = shading_error_bound(material, culled_irradiance_bound);
  if (!culled_radiance.bounded) return bound;
  for (int c = 0; c < 3; ++c) {
    // NaN-safe: only a radiance bound known to be smaller replaces the other.
    if (culled_radiance.bound[c] < bound[c]) bound[c] = culled_radiance.bound[c];
  }
  return bound;
}

double error_bound_pct(const glm::vec3& mean_bound) {
  double sum = 0.0;
  // A NaN bound would say nothing: it counts as the largest error a channel can have.
  for (int c = 0; c < 3; ++c)
    sum += std::isnan(mean_bound[c]) ? 1.0 : std::min(double{mean_bound[c]}, 1.0);
  return 100.0 * sum * 255.0 / 765.0;
}

glm::vec3 pixel_error_bound_mean(const Framebuffer& framebuffer, std::size_t i) {
  if (framebuffer.samples[i] == 0) return glm::vec3(0.0f);
  return framebuffer.error_bound_sum[i] / static_cast<float>(framebuffer.samples[i]);
}

double pixel_error_bound_pct(const Framebuffer& framebuffer, std::size_t i) {
  if (framebuffer.samples[i] == 0) return 0.0;
  return error_bound_pct(pixel_error_bound_mean(framebuffer, i) * framebuffer.exposure_scale);
}

std::vector<double> error_bound_pct_image(const Framebuffer& framebuffer) {
  std::vector<double> pct(framebuffer.samples.size());
  for (std::size_t i = 0; i < pct.size(); ++i) pct[i] = pixel_error_bound_pct(framebuffer, i);
  return pct;
}

std::vector<double> rendered_error_bound_pct(const Framebuffer& framebuffer) {
  std::vector<double> pct;
  for (std::size_t i = 0; i < framebuffer.samples.size(); ++i) {
    if (framebuffer.samples[i] != 0) pct.push_back(pixel_error_bound_pct(framebuffer, i));
  }
  return pct;
}

bool within_error_bound(double error_pct, double bound_pct) {
  // Room for the double rounding of the two percentages.
  return error_pct <= bound_pct + kErrorBoundRoundingPct + 1e-9;
}

PixelErrorStats error_bound_stats(const FramebufferTotals& totals) {
  PixelErrorStats s;
  if (totals.pixels_sampled == 0) return s;
  s.average_pct = totals.error_bound_pct_sum / static_cast<double>(totals.pixels_sampled);
  s.max_pct = totals.error_bound_pct_max;
  return s;
}

}  // namespace renderer
