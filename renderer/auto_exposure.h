// `--exposure auto`: the exposure a scene opens with, chosen before the first pass from a cheap
// estimate of the image. The rule: render a coarse preview (kAutoExposurePreviewWidth pixels
// wide, the image's aspect) with the unbiased `light_tree` method (kAutoExposureLightsPerPoint
// lights per point, kAutoExposurePasses passes at pixel centres, seed 0: deterministic), take
// the 99th percentile of its pixels' luminance, and pick the EV that puts that luminance where
// the display curve shows kAutoExposureDisplayedTarget (0.75, the middle of the 0.5..1.0 band a
// well-exposed image's 99th percentile lies in), but never a luminance below the median of the
// lit pixels (luminance above 0): a lit object on less than 2 % of a black frame is exposed by its
// own median rather than by the black around it (below 1 % the percentile is 0, which kept EV 0
// and showed a photometric scene far too bright). A black preview keeps EV 0.
#pragma once

#include <atomic>

#include "renderer/display_transform.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "renderer/scene.h"

namespace renderer {

inline constexpr int kAutoExposurePreviewWidth = 96;
inline constexpr int kAutoExposureLightsPerPoint = 16;
inline constexpr int kAutoExposurePasses = 2;
inline constexpr double kAutoExposurePercentile = 0.99;
inline constexpr float kAutoExposureDisplayedTarget = 0.75f;
// The EVs auto may pick.
inline constexpr double kAutoExposureMinEv = -64.0, kAutoExposureMaxEv = 64.0;

// The EV for the given (scene-linear) luminance percentile of an image under `curve`.
double exposure_for_percentile(double luminance_percentile, DisplayCurve curve);

// The value at `fraction` (0..1) of the sorted luminances of the pixels with a sample (with
// `lit_only`, of those whose luminance is above 0; 0 when there are none).
double luminance_percentile(const Framebuffer& framebuffer, double fraction, bool lit_only = false);

// The luminance the auto exposure shows at its target: the percentile of every pixel, at least
// the median of the lit ones.
inline constexpr double kAutoExposureLitFloorFraction = 0.5;
double auto_exposure_luminance(const Framebuffer& framebuffer);

// The auto exposure of the scene seen with `settings` (its size gives the preview's aspect, its
// depth and threads are used; method, tolerance and passes are the rule's own). When *cancel is
// raised the preview stops and EV 0 is returned.
double auto_exposure_ev(const Scene& scene, const RayScene& rays, const RenderSettings& settings,
                        DisplayCurve curve, const std::atomic<bool>* cancel = nullptr);

}  // namespace renderer
