#include "renderer/display_transform.h"

#include <algorithm>
#include <cmath>

namespace renderer {

namespace {

constexpr DisplayCurve kCurves[] = {DisplayCurve::linear, DisplayCurve::srgb,
                                    DisplayCurve::neutral};

}  // namespace

const char* display_curve_name(DisplayCurve curve) {
  switch (curve) {
    case DisplayCurve::linear:
      return "linear";
    case DisplayCurve::srgb:
      return "srgb";
    case DisplayCurve::neutral:
      return "neutral";
  }
  return "linear";
}

std::optional<DisplayCurve> parse_display_curve(std::string_view name) {
  for (DisplayCurve c : kCurves) {
    if (name == display_curve_name(c)) return c;
  }
  return std::nullopt;
}

std::vector<std::string> display_curve_names() {
  std::vector<std::string> names;
  for (DisplayCurve c : kCurves) names.emplace_back(display_curve_name(c));
  return names;
}

float exposure_scale(double exposure_ev) {
  return static_cast<float>(std::exp2(exposure_ev));
}

float srgb_encode(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 pbr_neutral(glm::vec3 colour) {
  // Khronos PBR Neutral (2024): a toe offset below 0.08, identity up to the start of
  // compression, then the peak channel compressed towards 1 and the colour desaturated by the
  // compression it took.
  constexpr float kStartCompression = 0.8f - 0.04f;
  constexpr float kDesaturation = 0.15f;
  const float lowest = std::min(colour.x, std::min(colour.y, colour.z));
  const float offset = lowest < 0.08f ? lowest - 6.25f * lowest * lowest : 0.04f;
  colour -= offset;
  const float peak = std::max(colour.x, std::max(colour.y, colour.z));
  if (peak < kStartCompression) return colour;
  constexpr float d = 1.0f - kStartCompression;
  const float new_peak = 1.0f - d * d / (peak + d - kStartCompression);
  colour *= new_peak / peak;
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - new_peak) + 1.0f);
  return glm::mix(colour, glm::vec3(new_peak), g);
}

glm::vec3 display_colour(const glm::vec3& radiance, float scale, DisplayCurve curve) {
  glm::vec3 exposed;
  for (int c = 0; c < 3; ++c) {
    exposed[c] = std::isnan(radiance[c]) ? 0.0f : std::max(radiance[c] * scale, 0.0f);
  }
  switch (curve) {
    case DisplayCurve::linear:
      return glm::min(exposed, glm::vec3(1.0f));
    case DisplayCurve::srgb:
      return {srgb_encode(exposed.x), srgb_encode(exposed.y), srgb_encode(exposed.z)};
    case DisplayCurve::neutral: {
      // An infinite channel is the brightest the tone map shows.
      const glm::vec3 mapped = pbr_neutral(glm::min(exposed, glm::vec3(1e30f)));
      return {srgb_encode(mapped.x), srgb_encode(mapped.y), srgb_encode(mapped.z)};
    }
  }
  return glm::min(exposed, glm::vec3(1.0f));
}

void display_rgb8(const glm::vec3& radiance, float scale, DisplayCurve curve, std::uint8_t* rgb) {
  if (curve == DisplayCurve::linear) {
    // framebuffer_rgb8's arithmetic, step for step, so linear at EV 0 (scale 1) matches it.
    for (int c = 0; c < 3; ++c) {
      const float exposed = radiance[c] * scale;
      const float v = std::isnan(exposed) ? 0.0f : std::clamp(exposed, 0.0f, 1.0f);
      rgb[c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }
    return;
  }
  const glm::vec3 shown = display_colour(radiance, scale, curve);
  for (int c = 0; c < 3; ++c) rgb[c] = static_cast<std::uint8_t>(std::lround(shown[c] * 255.0f));
}

std::vector<std::uint8_t> display_framebuffer_rgb8(const Framebuffer& f, const Display& display) {
  const float scale = exposure_scale(display.exposure_ev);
  std::vector<std::uint8_t> rgb(f.radiance_sum.size() * 3, 0);
  for (std::size_t i = 0; i < f.radiance_sum.size(); ++i) {
    if (f.samples[i] == 0) continue;
    const glm::vec3 mean = f.radiance_sum[i] / static_cast<float>(f.samples[i]);
    display_rgb8(mean, scale, display.curve, &rgb[3 * i]);
  }
  return rgb;
}

float exposed_grey_for_display(float displayed, DisplayCurve curve) {
  // Bisection on the grey the curve maps: every curve is increasing on [0, inf).
  float lo = 0.0f, hi = 1.0f;
  while (display_colour(glm::vec3(hi), 1.0f, curve).x < displayed && hi < 1e6f) hi *= 2.0f;
  for (int i = 0; i < 60; ++i) {
    const float mid = 0.5f * (lo + hi);
    (display_colour(glm::vec3(mid), 1.0f, curve).x < displayed ? lo : hi) = mid;
  }
  return 0.5f * (lo + hi);
}

}  // namespace renderer
