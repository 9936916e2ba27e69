// The smooth spot profile of glTF's KHR_lights_punctual: full intensity inside the inner cone,
// none outside the outer cone, and between them the square of a linear ramp in cos(gamma), as
// the extension's recommended implementation computes it. It replaces Warn's cos^P (thesis
// eq. 5) for such spots and never exceeds 1, so the cone cut by the extent sphere (thesis fig.
// 3.1) stays a conservative extent volume for it.
#pragma once

#include <algorithm>

namespace lev {

enum class SpotProfile : unsigned char {
  warn,    // cos(gamma)^P inside a hard cone (thesis eq. 5)
  smooth,  // glTF: ramp from the outer cone (0) to the inner cone (1)
};

// The extension's lightAngleScale floor: an inner cone as wide as the outer one still ramps
// over 1e-3 in cos(gamma) instead of dividing by zero.
inline constexpr float kMinSmoothConeCosWidth = 1e-3f;

// Angular attenuation of the smooth profile at cos(gamma), in [0, 1]:
// t = clamp((cos_gamma - cos_outer) / max(1e-3, cos_inner - cos_outer), 0, 1), then t^2.
inline float smooth_spot_attenuation(float cos_gamma, float cos_outer, float cos_inner) {
  const float scale = 1.0f / std::max(kMinSmoothConeCosWidth, cos_inner - cos_outer);
  const float t = std::clamp((cos_gamma - cos_outer) * scale, 0.0f, 1.0f);
  return t * t;
}

}  // namespace lev
