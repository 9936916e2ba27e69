// `ast`: Ward's adaptive shadow testing (thesis 2.5.1, fig. 2.8). At each point the potential
// contributions of all lights are ordered, the largest are shadow-tested until the untested rest
// sums (brightest channel) below the tolerance, and the rest is added scaled by how often that
// light was found visible before (or, for a light never tested, by this point's hit ratio).
//
// Determinism under threads: the per-light hit/test counters read while shading are a snapshot
// frozen at the start of the pass; tests made during the pass go to separate atomic counters and
// are folded into the snapshot in end_pass(). Integer sums do not depend on the order in which
// threads add them, so every pass, and the image, is the same whatever the thread count or
// tile order.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

struct AstCandidate {
  float potential = 0.0f;  // scalar (brightest channel) unshadowed contribution
  std::uint32_t light = 0;
  glm::vec3 radiance{0.0f};
};

// One thread's candidate heap, reused from point to point.
struct AstScratch final : MethodScratch {
  std::vector<AstCandidate> candidates;
};

class AstSelector final : public LightSelector {
 public:
  AstSelector(const LightHierarchy& hierarchy, float tolerance);
  glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                            SelectionCounters& counters,
                            glm::vec3* culled_irradiance_bound = nullptr) const override;
  void end_pass() override;
  bool learns_between_passes() const override { return true; }
  std::size_t bookkeeping_bytes() const override;
  std::unique_ptr<MethodScratch> make_scratch() const override {
    return std::make_unique<AstScratch>();
  }

 private:
  const double tolerance_;
  std::vector<Light> world_lights_;
  std::vector<std::uint32_t> hits_, tests_;  // snapshot: previous passes
  std::unique_ptr<std::atomic<std::uint32_t>[]> pass_hits_, pass_tests_;  // this pass
};

}  // namespace lev
