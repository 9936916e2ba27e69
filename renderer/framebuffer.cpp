#include "renderer/framebuffer.h"

#include <algorithm>
#include <cmath>

#include "renderer/error_bound.h"

namespace renderer {

Framebuffer make_framebuffer(int width, int height) {
  Framebuffer f;
  f.width = width;
  f.height = height;
  clear_framebuffer(f);
  return f;
}

void clear_framebuffer(Framebuffer& f) {
  const auto n = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height);
  f.radiance_sum.assign(n, glm::vec3(0.0f));
  f.samples.assign(n, 0);
  f.shading_points.assign(n, 0);
  f.lights_tested.assign(n, 0);
  f.nodes_visited.assign(n, 0);
  f.shadow_rays.assign(n, 0);
  f.error_bound_sum.assign(n, glm::vec3(0.0f));
  f.radiance_square_sum.assign(n, glm::dvec3(0.0));
  if (!f.missed_sum.empty()) allocate_missed_light(f);
}

void allocate_missed_light(Framebuffer& f) {
  const auto n = static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height);
  f.missed_sum.assign(n, glm::vec3(0.0f));
  f.missed_variance_sum.assign(n, glm::vec3(0.0f));
}

std::vector<std::uint8_t> framebuffer_rgb8(const Framebuffer& f) {
  std::vector<std::uint8_t> rgb(f.radiance_sum.size() * 3, 0);
  for (std::size_t i = 0; i < f.radiance_sum.size(); ++i) {
    if (f.samples[i] == 0) continue;
    const glm::vec3 mean = f.radiance_sum[i] / static_cast<float>(f.samples[i]) * f.exposure_scale;
    for (int c = 0; c < 3; ++c) {
      const float v = std::isnan(mean[c]) ? 0.0f : std::clamp(mean[c], 0.0f, 1.0f);
      rgb[3 * i + c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }
  }
  return rgb;
}

void add_pixel_totals(const Framebuffer& f, std::size_t i, FramebufferTotals& t) {
  t.samples += f.samples[i];
  t.shading_points += f.shading_points[i];
  t.lights_tested += f.lights_tested[i];
  t.nodes_visited += f.nodes_visited[i];
  t.shadow_rays += f.shadow_rays[i];
  if (f.shading_points[i] > 0) {
    const auto per_point = static_cast<std::uint32_t>(f.lights_tested[i] / f.shading_points[i]);
    t.lights_tested_max = std::max(t.lights_tested_max, per_point);
  }
  if (f.samples[i] > 0) {
    const double bound_pct = pixel_error_bound_pct(f, i);
    t.pixels_sampled += 1;
    t.error_bound_pct_sum += bound_pct;
    t.error_bound_pct_max = std::max(t.error_bound_pct_max, bound_pct);
  }
}

void add_totals(const FramebufferTotals& other, FramebufferTotals& t) {
  t.samples += other.samples;
  t.shading_points += other.shading_points;
  t.lights_tested += other.lights_tested;
  t.nodes_visited += other.nodes_visited;
  t.shadow_rays += other.shadow_rays;
  t.lights_tested_max = std::max(t.lights_tested_max, other.lights_tested_max);
  t.pixels_sampled += other.pixels_sampled;
  t.error_bound_pct_sum += other.error_bound_pct_sum;
  t.error_bound_pct_max = std::max(t.error_bound_pct_max, other.error_bound_pct_max);
}

FramebufferTotals sum_framebuffer(const Framebuffer& f) {
  FramebufferTotals t;
  for (std::size_t i = 0; i < f.samples.size(); ++i) add_pixel_totals(f, i, t);
  return t;
}

}  // namespace renderer
