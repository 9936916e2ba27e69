#include "app/viewer/heatmap_scale.h"

#include <algorithm>
#include <cmath>

namespace app::viewer {

const std::uint8_t kMaskRgb[3] = {245, 40, 60};

glm::u8vec3 diverging_rgb8(double t) {
  const glm::vec3 white(235.0f, 235.0f, 235.0f);
  const glm::vec3 blue(40.0f, 90.0f, 220.0f);
  const glm::vec3 red(215.0f, 35.0f, 40.0f);
  const double clamped = std::isnan(t) ? 0.0 : std::clamp(t, -1.0, 1.0);
  const glm::vec3 end = clamped < 0.0 ? blue : red;
  const glm::vec3 c = glm::mix(white, end, static_cast<float>(std::abs(clamped)));
  return glm::u8vec3(glm::round(c));
}

}  // namespace app::viewer
