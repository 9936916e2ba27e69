#include "renderer/auto_exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "renderer/render_service.h"

namespace renderer {

double exposure_for_percentile(double luminance_percentile, DisplayCurve curve) {
  if (!(luminance_percentile > 0.0) || !std::isfinite(luminance_percentile)) return 0.0;
  const double target = exposed_grey_for_display(kAutoExposureDisplayedTarget, curve);
  return std::clamp(std::log2(target / luminance_percentile), kAutoExposureMinEv,
                    kAutoExposureMaxEv);
}

double luminance_percentile(const Framebuffer& f, double fraction, bool lit_only) {
  std::vector<float> values;
  values.reserve(f.radiance_sum.size());
  for (std::size_t i = 0; i < f.radiance_sum.size(); ++i) {
    if (f.samples[i] == 0) continue;
    const float y = luminance(f.radiance_sum[i] / static_cast<float>(f.samples[i]));
    const float value = std::isfinite(y) ? std::max(y, 0.0f) : 0.0f;
    if (!lit_only || value > 0.0f) values.push_back(value);
  }
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(
      std::clamp(fraction, 0.0, 1.0) * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

double auto_exposure_luminance(const Framebuffer& f) {
  return std::max(luminance_percentile(f, kAutoExposurePercentile),
                  luminance_percentile(f, kAutoExposureLitFloorFraction, true));
}

double auto_exposure_ev(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                        DisplayCurve curve, const std::atomic<bool>* cancel) {
  RenderSettings preview;
  preview.width = std::min(settings.width, kAutoExposurePreviewWidth);
  preview.height = std::max(1, static_cast<int>(std::lround(static_cast<double>(preview.width) *
                                                            settings.height / settings.width)));
  preview.max_depth = settings.max_depth;
  preview.threads = settings.threads;
  preview.method = lev::Method::light_tree;
  preview.lights_per_point = kAutoExposureLightsPerPoint;
  preview.jitter_pixels = false;
  RenderResult result;
  if (!render_passes(scene, rays, preview, kAutoExposurePasses, result, cancel)) return 0.0;
  return exposure_for_percentile(auto_exposure_luminance(result.framebuffer), curve);
}

}  // namespace renderer
