// A made-up pixel inspection whose values include NaN, +-inf and ties, as a broken light or a
// degenerate scene can give: the inspector's sorts (renderer::ranks_before) must order it totally
// instead of meeting an invalid comparator. Each light's x position is its place in the record
// (shaded terms first, then the culled lights), so a test can tell which row came from where.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "renderer/pixel_inspection.h"

namespace levrt_test {

// The brightest channel of each row in record order: every fourth is NaN, some +inf or -inf, many
// equal; enough rows (more than std::sort's insertion-sort cut of 16) to reach its partitioning.
inline std::vector<float> odd_contributions() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values;
  for (int i = 0; i < 48; ++i) {
    if (i % 4 == 0) {
      values.push_back(nan);
    } else if (i == 5) {
      values.push_back(inf);
    } else if (i == 9) {
      values.push_back(-inf);
    } else {
      values.push_back(static_cast<float>(i % 3));  // 0, 1, 2 over and over: ties
    }
  }
  return values;
}

// One primary hit: the first half of odd_contributions() as tested lights (their contribution
// and unshadowed radiance the value), the rest as culled lights seen by their shadow ray.
inline renderer::PixelInspection odd_inspection() {
  renderer::PixelInspection inspection;
  renderer::InspectedHit& hit = inspection.hits.emplace_back();
  const std::vector<float> values = odd_contributions();
  for (std::size_t i = 0; i < values.size(); ++i) {
    lev::Light light;
    light.position = glm::vec3(static_cast<float>(i), 0.0f, 0.0f);
    const glm::vec3 value(values[i], 0.0f, 0.0f);
    if (i < values.size() / 2) {
      lev::ShadedLight& s = hit.record.shaded.emplace_back();
      s.light = light;
      s.unshadowed_radiance = value;
      s.contribution = value;
      s.shadow_ray = true;
      s.visible = true;
    } else {
      lev::InspectedLight& c = hit.record.culled.emplace_back();
      c.light = light;
      c.unshadowed_radiance = value;
      c.visible = true;
    }
  }
  inspection.totals = renderer::hit_totals(hit);
  return inspection;
}

// The record place (x position) of the rows, as listed, must follow this order: |value|
// descending, +-inf first, NaN last, equal values by record place.
inline std::vector<std::size_t> odd_expected_order() {
  const std::vector<float> values = odd_contributions();
  std::vector<std::size_t> finite, nan;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] != values[i]) {
      nan.push_back(i);
    } else {
      finite.push_back(i);
    }
  }
  std::vector<std::size_t> order;
  // A selection by hand, independent of the code under test: largest magnitude first.
  while (!finite.empty()) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < finite.size(); ++k) {
      const float a = values[finite[k]] < 0 ? -values[finite[k]] : values[finite[k]];
      const float b = values[finite[best]] < 0 ? -values[finite[best]] : values[finite[best]];
      if (a > b) best = k;
    }
    order.push_back(finite[best]);
    finite.erase(finite.begin() + static_cast<std::ptrdiff_t>(best));
  }
  order.insert(order.end(), nan.begin(), nan.end());
  return order;
}

}  // namespace levrt_test
