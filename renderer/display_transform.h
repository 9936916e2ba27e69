// From scene-linear radiance to the displayed image. The renderer's radiance stays
// scene-linear; a display step turns it into what is shown and written: multiply by the
// exposure, 2^EV, then apply a display curve and round to 8 bits. The curves: `linear` (the
// exposed value clipped to [0, 1], 1.0 = 255: the images levrt always wrote, so linear at EV 0 is
// framebuffer_rgb8 bit for bit), `srgb` (the sRGB transfer function, IEC 61966-2-1) and
// `neutral` (Khronos PBR Neutral tone mapping, then sRGB). The exposed linear values (radiance x
// 2^EV, before the curve) are the displayed units that the tolerance and every error metric use.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/framebuffer.h"

namespace renderer {

enum class DisplayCurve : std::uint8_t { linear, srgb, neutral };

const char* display_curve_name(DisplayCurve curve);
std::optional<DisplayCurve> parse_display_curve(std::string_view name);
std::vector<std::string> display_curve_names();

struct Display {
  double exposure_ev = 0.0;  // the displayed value is radiance x 2^exposure_ev, then the curve
  DisplayCurve curve = DisplayCurve::linear;
};

// 2^ev as the float every display step multiplies by (exactly 1 at EV 0).
float exposure_scale(double exposure_ev);

// The sRGB encoding of one linear value in [0, 1].
float srgb_encode(float linear);
// Khronos PBR Neutral tone mapping of an exposed linear colour (each channel >= 0); the result
// lies in [0, 1).
glm::vec3 pbr_neutral(glm::vec3 colour);

// One mean radiance through the display step, each channel in [0, 1] (NaN shows as 0).
glm::vec3 display_colour(const glm::vec3& radiance, float exposure_scale, DisplayCurve curve);
// The same, as 8 bits per channel.
void display_rgb8(const glm::vec3& radiance, float exposure_scale, DisplayCurve curve,
                  std::uint8_t* rgb);

// The framebuffer's mean radiance through the display step; pixels without a sample are black.
std::vector<std::uint8_t> display_framebuffer_rgb8(const Framebuffer& framebuffer,
                                                   const Display& display);

// Rec. 709 luminance of a linear or displayed colour.
inline float luminance(const glm::vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// The exposed linear grey that `curve` displays as `displayed` (in (0, 1)): the inverse of the
// curve on grey, for choosing an exposure.
float exposed_grey_for_display(float displayed, DisplayCurve curve);

}  // namespace renderer
