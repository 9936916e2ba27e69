// The interface every many-light method implements: given a shading point, decide which lights
// get a shadow ray and return the direct radiance (the sum term of eq. 7). The renderer supplies
// the surface (ShadingPoint) and stays the same for every method. Every row of the method table
// (lev/methods.cpp) implements it; a sampling method gets a per-sample random stream for free.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "lev/important_lights.h"
#include "lev/inspect_record.h"
#include "lev/light.h"

namespace lev {

// What a method may ask of the surface being shaded. Implemented by the renderer.
class ShadingPoint {
 public:
  virtual ~ShadingPoint() = default;
  virtual glm::vec3 position() const = 0;
  // The unit normal on the side a light must be on to add anything (unshadowed_radiance is zero
  // from the other side), for methods that sample by importance; zero when unknown.
  virtual glm::vec3 normal() const { return glm::vec3(0.0f); }
  // Radiance the light would add toward the viewer if unoccluded: eq. 6 without the ambient
  // term. Zero when the light is behind the surface; finite (at most the largest float).
  virtual glm::vec3 unshadowed_radiance(const Light& world_light) const = 0;
  // Casts one shadow ray; true when nothing blocks the light. It depends on the light's position
  // alone (lev_cut answers a second ray to one position from the first: selector_lev_cut.cpp).
  virtual bool visible(const Light& world_light) = 0;
  // The material's side of a cluster's bound (light_bounds.h): what unshadowed_radiance can
  // be per unit irradiance from a box of positions. The default, for a point that does not say,
  // bounds nothing (an infinite response): a method that clusters refines down to single lights.
  virtual SurfaceResponse surface_response() const {
    SurfaceResponse unknown;
    unknown.diffuse = glm::vec3(std::numeric_limits<float>::infinity());
    return unknown;
  }
};

struct SelectionCounters {
  std::uint64_t lights_tested = 0;  // lights selected for a shadow test
  std::uint64_t nodes_visited = 0;  // extent volumes tested (LEV walks)
  std::uint64_t shadow_rays =
      0;  // rays actually cast (a selected light behind the surface needs none)
  // Lights whose unshadowed radiance a method summed beyond those it tested (lev_cut's exact
  // clusters' lights): work the rt fallback's probe weighs (WorkCost::per_light_evaluated).
  std::uint64_t lights_evaluated = 0;
};

// A small random stream seeded per (pixel, sample) by the renderer, so that methods that sample
// stay independent of thread count and tile order. splitmix64.
struct RandomStream {
  std::uint64_t state = 0;
  std::uint64_t next_u64() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float next_float() { return static_cast<float>(next_u64() >> 40) * 0x1.0p-24f; }
  double next_double() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
};

// A request for the missed light at one shading point (lev/missed_light.h), set in
// SelectorScratch::missed by the renderer when asked: a method that leaves light out estimates
// (rt's direct radiance - its own) from `draws` draws of what it left out, with shadow rays,
// and the variance of that estimate; rt and the sampling methods, which leave nothing out on
// average, leave `estimated` false.
struct MissedLight {
  int draws = 0;                   // K >= 2
  RandomStream* random = nullptr;  // its own stream: the method's image never depends on it
  bool estimated = false;          // out
  glm::vec3 radiance{0.0f};        // out: negative where a method's stand-in overshoots
  glm::vec3 variance{0.0f};        // out: of that estimate
};

// A method's own per-thread buffers (AST's candidate heap), made by its selector
// (LightSelector::make_scratch) the first time a thread shades with it and reused after.
class MethodScratch {
 public:
  virtual ~MethodScratch() = default;
};

// Per-thread buffers a method may reuse between shading points. One scratch serves one method
// (the renderer keeps one per thread per render state).
struct SelectorScratch {
  // Raised by the caller to stop a render: long light loops read it every kCancelCheckLights
  // lights and return early (the caller discards that result).
  const std::atomic<bool>* cancel = nullptr;
  std::vector<Light> lights;  // for methods that select a list of lights (lev's walk)
  WalkScratch walk;           // for methods that walk the hierarchy
  RandomStream random;
  std::unique_ptr<MethodScratch> method;  // from the selector's make_scratch (null: none)
  // Set by the caller for one call when it wants the missed light estimated (null: not asked),
  // and the estimate's buffers (lev/missed_light.h), made on first use.
  MissedLight* missed = nullptr;
  std::unique_ptr<MethodScratch> missed_scratch;
  // Set by the caller for one call when it inspects the point (the pixel inspector,
  // lev/inspect_record.h), with walk.inspect the same: the method records there what it shaded,
  // culled and clustered. Null in renders.
  InspectRecord* inspect = nullptr;
  // Set by the caller for one call, with culled_irradiance_bound: a method that bounds, at the
  // point's own surface, the radiance error of what it did not shade exactly (what it left out
  // or estimated: CulledRadianceBound, important_lights.h; lev, lev_est, lev_cut, ast,
  // lightcuts) answers there; the others leave it unanswered (bounded false).
  CulledRadianceBound* culled_radiance = nullptr;
};

class LightSelector {
 public:
  virtual ~LightSelector() = default;
  // The direct radiance at the point. When culled_irradiance_bound is given it also receives an
  // upper bound of the summed unshadowed irradiance (RGB, light.h's irradiance()) of the lights the
  // method neither shadow-tested nor accounted for exactly: the error the method may make, before
  // the material. The default argument lets callers that do not want it (and skip its cost) keep
  // three arguments; every override repeats the same default, nullptr.
  virtual glm::vec3 direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                    SelectionCounters& counters,
                                    glm::vec3* culled_irradiance_bound = nullptr) const = 0;
  // Called by the renderer after every complete pass (never concurrently with direct_radiance).
  virtual void end_pass() {}
  // True when what direct_radiance does depends on the points shaded in earlier passes (AST's
  // visibility statistics, folded in end_pass). A selector that does not learn can shade a
  // preview or the pixel inspector's point too; one that does needs a second selector for
  // them, or they would teach it.
  virtual bool learns_between_passes() const { return false; }
  // Memory the method keeps besides the light hierarchy (AST's per-light statistics).
  virtual std::size_t bookkeeping_bytes() const { return 0; }
  // The buffers of this method for one thread, kept in SelectorScratch::method; null for none.
  virtual std::unique_ptr<MethodScratch> make_scratch() const { return nullptr; }

 protected:
  // This method's buffers in `scratch`, made on first use.
  template <typename Scratch>
  Scratch& method_scratch(SelectorScratch& scratch) const {
    if (!scratch.method) scratch.method = make_scratch();
    return static_cast<Scratch&>(*scratch.method);
  }
};

// The shading loop shared by rt and lev: every selected light is counted as tested and, when it
// can light the surface at all, gets a shadow ray. Summation order is the order of `lights`.
// The sum is kept in double and rounded to float once: a float running sum of a million similar
// terms drifts by up to 1% (each term is rounded against an ever larger sum), a double one stays
// within one float rounding of the exact sum. Clamped to the largest float on the way back, as
// irradiance() clamps each term, so that huge lights never overflow the conversion.
// cancel (may be null) is read every kCancelCheckLights lights; once raised the sum so far is
// returned, which the caller discards. visible_irradiance (may be null) gains the brightest
// channel of irradiance() of each light found visible. record (may be null: the inspector's,
// SelectorScratch::inspect) gains each selected light as shaded and each other as culled by its
// own test. shadow_target(i, light), called for the i-th light of `lights` once it can light the
// surface, names the light its shadow ray goes to instead (a cluster's member: lev_cut), or
// returns null for the light itself. unshadowed (may be null) holds, per light of `lights`, its
// point.unshadowed_radiance already computed (lev_cut's walk computes it for its running total).
// ray_visible (may be null; one entry per light of `lights`) is set to 1 where a light's shadow ray
// found it and to 0 where the ray was blocked; a light without a ray keeps its entry (lev_cut's
// visibility_noise).
inline constexpr std::size_t kCancelCheckLights = 4096;
struct ShadowRayToTheLight {
  const Light* operator()(std::size_t, const Light&) const { return nullptr; }
};
template <typename LightRange, typename Filter, typename ShadowTarget = ShadowRayToTheLight>
glm::vec3 sum_visible_lights(const LightRange& lights, Filter&& selected, ShadingPoint& point,
                             SelectionCounters& counters, const std::atomic<bool>* cancel = nullptr,
                             float* visible_irradiance = nullptr, InspectRecord* record = nullptr,
                             ShadowTarget&& shadow_target = ShadowTarget{},
                             const glm::vec3* unshadowed = nullptr,
                             std::uint8_t* ray_visible = nullptr) {
  glm::dvec3 sum(0.0);
  std::size_t index = 0;
  for (const Light& light : lights) {
    const std::size_t i = index++;
    if (cancel && index % kCancelCheckLights == 0 && cancel->load(std::memory_order_relaxed)) break;
    if (!selected(light)) {
      if (record) record->culled_lights.push_back(light);
      continue;
    }
    ++counters.lights_tested;
    const glm::vec3 radiance = unshadowed ? unshadowed[i] : point.unshadowed_radiance(light);
    ShadedLight* shaded = nullptr;
    if (record) {
      shaded = &record->shaded.emplace_back();
      shaded->light = light;
      shaded->unshadowed_radiance = radiance;
    }
    if (radiance == glm::vec3(0.0f)) continue;
    ++counters.shadow_rays;
    const Light* target = shadow_target(i, light);
    const bool visible = point.visible(target ? *target : light);
    if (ray_visible) ray_visible[i] = visible ? 1 : 0;
    if (shaded) {
      shaded->shadow_ray = true;
      shaded->visible = visible;
      if (visible) shaded->contribution = radiance;
    }
    if (!visible) continue;
    sum += glm::dvec3(radiance);
    if (visible_irradiance) *visible_irradiance += brightest(irradiance(light, point.position()));
  }
  return glm::vec3(glm::min(sum, glm::dvec3(std::numeric_limits<float>::max())));
}

}  // namespace lev
