// What the two sampling methods (lev_mc, light_tree) share as selectors: the hierarchy they draw
// from, k (the lights drawn per shading point), their per-thread buffers (SamplingScratch), and
// the answer to culled_irradiance_bound: +inf, as a sampled estimate has no certified bound
// (lev_mc answers 0 where its walk culled nothing: its radiance is then rt's).
#pragma once

#include <limits>
#include <memory>

#include "lev/light_hierarchy.h"
#include "lev/light_sampling.h"
#include "lev/light_selector.h"

namespace lev {

class SamplingSelector : public LightSelector {
 public:
  std::unique_ptr<MethodScratch> make_scratch() const final {
    return std::make_unique<SamplingScratch>();
  }

 protected:
  // lights_per_point: k, the lights drawn at each shading point (>= 1).
  SamplingSelector(const LightHierarchy& hierarchy, int lights_per_point)
      : hierarchy_(hierarchy), lights_per_point_(lights_per_point) {}

  // The thread's buffers; stores the (infinite) bound when asked for one.
  SamplingScratch& begin_point(SelectorScratch& scratch, glm::vec3* culled_irradiance_bound) const {
    if (culled_irradiance_bound)
      *culled_irradiance_bound = glm::vec3(std::numeric_limits<float>::infinity());
    return method_scratch<SamplingScratch>(scratch);
  }

  const LightHierarchy& hierarchy_;
  const int lights_per_point_;
};

}  // namespace lev
