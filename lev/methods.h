// The table of many-light methods: one row per method, and everything the front ends need to
// know about it. The CLI (--method and its help), the viewer (method switch, tooltips, trade
// plot), the render service and the benchmarks read only this table.
//
// Adding a method:
//   1. its selector, lev/selector_NAME.{h,cpp}: a LightSelector (with make_scratch when it keeps
//      per-thread buffers, and reading SelectorScratch::random when it samples);
//   2. its enum value in Method below, and its row in lev/methods.cpp: name, label, summary, its
//      traits (MethodTrait), the values the bench's trade experiment sweeps, and the function
//      that makes its selector from the MethodParams (the settings it reads).
// It then appears in `--method`, the viewer's method switch and trade plot, and the benchmarks
// that compare methods (speed, trade); nothing else names methods. A selector whose class no
// one else needs can be one file, selector_NAME.cpp, its make function declared beside its row:
// three files in all.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"

namespace lev {

// The tolerance a render uses unless told otherwise (colour units, 1.0 = 255): thesis Test 1.1.
inline constexpr double kDefaultTolerance = 0.01;

// A row of method_table(), by position. The named values are the built-in rows; the rows a
// program adds (extra_method_rows, lev/method_rows.h) take the next values.
enum class Method : std::uint8_t {
  rt,
  ast,
  lev,
  lev_bounded,
  lev_est,
  lev_mc,
  light_tree,
  lightcuts,
  lev_cut
};

// The lights a sampling method draws per shading point (--lights-per-point): 1 by default, at most
// this.
inline constexpr int kMaxLightsPerPoint = 1024;
// The relative error a render uses unless told otherwise (--relative-error): Walter et al.
// 2005's 2 %, below which a change in the light of a point is not seen (Weber's law).
inline constexpr double kDefaultRelativeError = 0.02;

// What a selector is made with: the method and the settings methods read (each only those its
// row says it uses).
struct MethodParams {
  Method method = Method::lev;
  float tolerance = static_cast<float>(kDefaultTolerance);           // >= 0, colour units
  float relative_error = static_cast<float>(kDefaultRelativeError);  // [0, 1]
  int lights_per_point =
      1;  // lights a sampling method draws per shading point, [1, kMaxLightsPerPoint]
  // The tolerance is in displayed units: scene-linear irradiance times this (the exposure, 2^EV;
  // > 0). A selector culls at tolerance / display_scale in the scene's own units, so a scene
  // 100x darker shown 6.64 EV brighter culls the same lights.
  float display_scale = 1.0f;
};

// The method a render uses and the settings methods read: the lev layer's group of the user's
// settings (app/settings.h composes it). Two choices compare equal when their method renders
// the same images with them: a setting the method does not read (its row's traits) is not
// compared, so changing it restarts nothing.
struct MethodChoice {
  Method method = Method::lev;
  double tolerance = kDefaultTolerance;           // colour units, 1.0 = 255
  double relative_error = kDefaultRelativeError;  // lightcuts: a cluster's bound / the total
  int lights_per_point = 1;  // lights a sampling method draws per shading point and pass
  // A deterministic method may shade with rt's loop where a probe of the frame says its walk
  // would cost more than rt's shadow rays save (renderer/rt_fallback.h); off: never.
  bool rt_fallback = true;
};

// The choice with every setting its method does not read at its default, so that choices equal
// under == are identical here (a cache key).
MethodChoice used_settings(const MethodChoice& choice);
bool operator==(const MethodChoice& a, const MethodChoice& b);
bool operator!=(const MethodChoice& a, const MethodChoice& b);

// The tolerance in the scene's units: params.tolerance / params.display_scale.
float scene_tolerance(const MethodParams& params);

using MakeSelector = std::unique_ptr<LightSelector> (*)(const LightHierarchy& hierarchy,
                                                        const MethodParams& params);

// What a row says of its method, or'ed together in the row (named, so a row reads as what it
// is).
enum MethodTrait : unsigned {
  kNoTraits = 0,
  kUsesTolerance = 1u << 0,      // reads MethodParams::tolerance
  kUsesRelativeError = 1u << 1,  // reads MethodParams::relative_error
  kIsReference = 1u << 2,        // exact: what every other method's errors are measured against
  kStochastic = 1u << 3,         // draws from the per-sample random stream
  kScansEveryLight = 1u << 4,    // its time per point grows with the light count
  // Reads MethodParams::display_scale beyond the tolerance (lev_cut's drop of what cannot reach
  // the display); a method with kUsesTolerance reads it through scene_tolerance already.
  kReadsDisplayScale = 1u << 5,
  // Estimates the light it left out when asked (MissedLight, lev/missed_light.h).
  kEstimatesMissedLight = 1u << 6,
};

// What a method's work at one shading point costs, in shadow rays, per unit of what it counts
// (SelectionCounters) and per light of the scene: the render's choice to shade a deterministic
// method with rt's loop instead (renderer/rt_fallback.h) weighs a probe's counts with it, never a
// clock, so that the choice is the same on every machine. Measured on the bench scenes
// (docs/results/rt_fallback.md): a shadow ray costs about 1 us there, an extent volume test a
// fifth of that, a light's radiance a few percent; AST's heap and Lightcuts' cluster bounds more.
struct WorkCost {
  double per_node_visited = 0.2;
  // Beyond its shadow ray, which counts apart: its unshadowed radiance, and what the method does
  // per light or cluster it tests (a heap's pop, a cluster's bound).
  double per_light_tested = 0.03;
  double per_scene_light = 0.0;  // a method that scans every light at every point
  // A light whose unshadowed radiance the method sums without a shadow test of its own
  // (SelectionCounters::lights_evaluated): placing it and shading it, no ray.
  double per_light_evaluated = 0.0;
};

struct MethodInfo {
  MethodInfo(Method id, const char* name, const char* label, const char* summary, unsigned traits,
             std::vector<double> bench_tolerances, MakeSelector make_selector,
             WorkCost work_cost = {});

  Method id;
  const char* name;     // CLI value and stats JSON
  const char* label;    // viewer
  const char* summary;  // CLI help and viewer tooltip
  bool uses_tolerance;  // false: the images do not depend on the tolerance (no restart, no refit)
  // Reads MethodParams::relative_error (--relative-error); images then depend on it.
  bool uses_relative_error;
  bool is_reference;  // exact: the images every other method's pixel errors are measured against
  bool stochastic;    // draws from the per-sample random stream (images depend on the passes)
  bool scans_every_light;  // its time per point grows with the light count: the bench subsamples it
  // Its images depend on the exposure (the tolerance, or a drop, in displayed units): a new
  // exposure renders it again. rt's radiance, and every sampler's, do not depend on it.
  bool reads_display_scale;
  // The missed-light estimate (lev/missed_light.h) is known for it: estimated from draws of what
  // it left out (kEstimatesMissedLight), or 0 by construction (rt, and the samplers, which leave
  // nothing out on average). False for a method that errs without estimating it (ast, lightcuts,
  // lev_cut): its estimate would read 0 where its pixels differ from rt's.
  bool missed_light_known;
  // The trade experiment's sweep, largest first: of the tolerance, or of the relative error for a
  // method that uses that and not the tolerance (swept_setting).
  std::vector<double> bench_tolerances;
  MakeSelector make_selector;
  WorkCost work_cost;
};

const std::vector<MethodInfo>& method_table();
const MethodInfo& method_info(Method method);
std::optional<Method> parse_method(std::string_view name);
// The one row with is_reference (rt).
Method reference_method();
// Whether a render of the method may fall back on rt's loop (MethodChoice::rt_fallback): every
// deterministic method but rt itself; a sampler's passes converge to rt's image anyway.
bool rt_fallback_applies(const MethodInfo& info);

// The selector for one render (params.lights_per_point in [1, kMaxLightsPerPoint], the relative
// error in [0, 1]; else std::invalid_argument). It reads the hierarchy (which it never changes, so
// any number of selectors may share it) and must not outlive it.
std::unique_ptr<LightSelector> make_selector(const LightHierarchy& hierarchy,
                                             const MethodParams& params);

// The setting the bench sweeps a method over (its row's bench_tolerances): the relative error
// for a method that uses it and not the tolerance, else the tolerance.
float MethodParams::*swept_setting(const MethodInfo& method);

}  // namespace lev
