#include "lev/methods.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "lev/method_rows.h"
#include "lev/selector_ast.h"
#include "lev/selector_lev.h"
#include "lev/selector_lev_bounded.h"
#include "lev/selector_lev_cut.h"
#include "lev/selector_lev_est.h"
#include "lev/selector_lev_mc.h"
#include "lev/selector_light_tree.h"
#include "lev/selector_lightcuts.h"
#include "lev/selector_rt.h"

namespace lev {

namespace {

std::vector<MethodInfo> built_in_rows() {
  return {
      {Method::rt,
       "rt",
       "RT (every light)",
       "a shadow ray to every light with non-zero irradiance",
       kIsReference | kScansEveryLight,
       {},
       [](const LightHierarchy& h, const MethodParams&) -> std::unique_ptr<LightSelector> {
         return std::make_unique<RtSelector>(h);
       },
       WorkCost{0.0, 0.03, 0.02}},
      {Method::ast,
       "ast",
       "AST (Ward 1991)",
       "adaptive shadow testing: test the largest potential contributions until the untested "
       "rest is below the tolerance, estimate the rest from hit ratios",
       kUsesTolerance | kScansEveryLight,
       {1.0, 0.3, 0.1, 0.03, 0.01},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<AstSelector>(h, scene_tolerance(p));
       },
       WorkCost{0.0, 0.5, 0.02}},
      {Method::lev,
       "lev",
       "LEV (extent volumes)",
       "walk the light extent volume hierarchy; shadow rays only to the lights returned",
       kUsesTolerance | kEstimatesMissedLight,
       {0.1, 0.03, 0.01, 0.003, 0.001},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LevSelector>(h, scene_tolerance(p));
       }},
      {Method::lev_bounded,
       "lev_bounded",
       "LEV bounded (guaranteed)",
       "LEV that culls only while the summed irradiance bound of what it culled at the point stays "
       "within the tolerance",
       // Where many lights add up it shadow-tests nearly all of them (building: 3,998 of 4,096).
       kUsesTolerance | kScansEveryLight | kEstimatesMissedLight,
       {0.1, 0.03, 0.01, 0.003, 0.001},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LevBoundedSelector>(h, scene_tolerance(p));
       }},
      {Method::lev_est,
       "lev_est",
       "LEV estimated (clusters)",
       "LEV, plus an estimate of what it culled: the culled subtrees cut into clusters, each a "
       "representative light with the cluster's intensity and one shadow ray (Lightcuts)",
       kUsesTolerance | kEstimatesMissedLight,
       {0.1, 0.03, 0.01, 0.003, 0.001},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LevEstSelector>(h, scene_tolerance(p), p.display_scale);
       }},
      {Method::lev_mc,
       "lev_mc",
       "LEV + sampled rest (unbiased)",
       "LEV's shadow rays, plus k lights (--lights-per-point) drawn from what the walk culled by "
       "their "
       "irradiance bound, weighed by 1/probability: passes converge to rt",
       kUsesTolerance | kStochastic,
       {0.1, 0.03, 0.01, 0.003, 0.001},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LevMcSelector>(h, scene_tolerance(p), p.lights_per_point);
       }},
      {Method::light_tree,
       "light_tree",
       "Light tree (pbrt-v4, Cycles)",
       "k lights (--lights-per-point) drawn from the whole hierarchy by importance (pbrt-v4's "
       "BVHLightSampler, Cycles' light tree), weighed by 1/probability: passes converge to rt",
       kStochastic,
       {},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LightTreeSelector>(h, p.lights_per_point);
       }},
      {Method::lightcuts,
       "lightcuts",
       "Lightcuts (Walter 2005)",
       "a cut through a binary light tree, refined until every cluster's error bound is below "
       "the relative error (--relative-error) times the point's estimate; one shadow ray per "
       "cluster's representative",
       kUsesRelativeError,
       {0.1, 0.05, 0.02, 0.01, 0.005},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LightcutsSelector>(h, p.relative_error);
       },
       WorkCost{0.0, 2.0, 0.0}},
      {Method::lev_cut,
       "lev_cut",
       "LEV cut (relative)",
       "LEV's walk, its volumes dropping what cannot reach the display (below the relative error "
       "times one 8-bit step), what they keep cut into clusters whose error bound is below the "
       "relative error (--relative-error) times the point's running total (at least a tenth of "
       "white); one shadow ray per "
       "cluster, and a finer cut where those rays find clusters partly hidden (their noise on the "
       "display above the relative error)",
       kUsesRelativeError | kReadsDisplayScale,
       {0.1, 0.05, 0.02, 0.01, 0.005},
       [](const LightHierarchy& h, const MethodParams& p) -> std::unique_ptr<LightSelector> {
         return std::make_unique<LevCutSelector>(h, p.relative_error, p.display_scale);
       },
       WorkCost{0.6, 0.03, 0.0, 0.15}},
  };
}

// The built-in rows and then the program's own (their ids the next values), checked once.
std::vector<MethodInfo> make_method_table() {
  std::vector<MethodInfo> table = built_in_rows();
  for (MethodInfo& row : extra_method_rows()) {
    for (const MethodInfo& known : table) {
      if (std::string_view(known.name) == row.name)
        throw std::logic_error(std::string("method '") + row.name + "' exists already");
    }
    if (row.is_reference) throw std::logic_error("method_table has its reference method already");
    row.id = static_cast<Method>(table.size());
    table.push_back(std::move(row));
  }
  return table;
}

}  // namespace

// The library's default: no rows beyond the built-in ones. Weak, so a program that defines its
// own extra_method_rows (a test binary's method) replaces it at link time, and the table stays
// one constant built once.
__attribute__((weak)) std::vector<MethodInfo> extra_method_rows() {
  return {};
}

MethodInfo::MethodInfo(Method id_, const char* name_, const char* label_, const char* summary_,
                       unsigned traits, std::vector<double> bench_tolerances_,
                       MakeSelector make_selector_, WorkCost work_cost_)
    : id(id_),
      name(name_),
      label(label_),
      summary(summary_),
      uses_tolerance((traits & kUsesTolerance) != 0),
      uses_relative_error((traits & kUsesRelativeError) != 0),
      is_reference((traits & kIsReference) != 0),
      stochastic((traits & kStochastic) != 0),
      scans_every_light((traits & kScansEveryLight) != 0),
      reads_display_scale((traits & (kUsesTolerance | kReadsDisplayScale)) != 0),
      missed_light_known((traits & (kEstimatesMissedLight | kIsReference | kStochastic)) != 0),
      bench_tolerances(std::move(bench_tolerances_)),
      make_selector(make_selector_),
      work_cost(work_cost_) {}

const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = make_method_table();
  return table;
}

const MethodInfo& method_info(Method method) {
  const std::vector<MethodInfo>& table = method_table();
  const auto index = static_cast<std::size_t>(method);
  if (index >= table.size()) throw std::logic_error("method missing from method_table");
  return table[index];
}

std::optional<Method> parse_method(std::string_view name) {
  for (const MethodInfo& info : method_table()) {
    if (name == info.name) return info.id;
  }
  return std::nullopt;
}

Method reference_method() {
  for (const MethodInfo& info : method_table()) {
    if (info.is_reference) return info.id;
  }
  throw std::logic_error("method_table has no reference method");
}

std::unique_ptr<LightSelector> make_selector(const LightHierarchy& hierarchy,
                                             const MethodParams& params) {
  if (params.lights_per_point < 1 || params.lights_per_point > kMaxLightsPerPoint) {
    throw std::invalid_argument("lights per point " + std::to_string(params.lights_per_point) +
                                " outside [1, " + std::to_string(kMaxLightsPerPoint) + "]");
  }
  if (!(params.display_scale > 0.0f) || !std::isfinite(params.display_scale)) {
    throw std::invalid_argument("display scale " + std::to_string(params.display_scale) +
                                " is not a finite number above 0");
  }
  if (!(params.relative_error >= 0.0f && params.relative_error <= 1.0f)) {
    throw std::invalid_argument("relative error " + std::to_string(params.relative_error) +
                                " outside [0, 1]");
  }
  return method_info(params.method).make_selector(hierarchy, params);
}

float scene_tolerance(const MethodParams& params) {
  return params.tolerance / params.display_scale;
}

float MethodParams::*swept_setting(const MethodInfo& method) {
  return method.uses_relative_error && !method.uses_tolerance ? &MethodParams::relative_error
                                                              : &MethodParams::tolerance;
}

bool rt_fallback_applies(const MethodInfo& info) {
  return !info.is_reference && !info.stochastic;
}

MethodChoice used_settings(const MethodChoice& choice) {
  const MethodInfo& info = method_info(choice.method);
  const MethodChoice defaults;
  MethodChoice used = choice;
  if (!info.uses_tolerance) used.tolerance = defaults.tolerance;
  if (!info.uses_relative_error) used.relative_error = defaults.relative_error;
  if (!info.stochastic) used.lights_per_point = defaults.lights_per_point;
  if (!rt_fallback_applies(info)) used.rt_fallback = defaults.rt_fallback;
  return used;
}

bool operator==(const MethodChoice& a, const MethodChoice& b) {
  // Binding every member: a member added to MethodChoice stops this compiling until it is
  // compared too.
  const auto [method, tolerance, relative_error, lights_per_point, rt_fallback] = used_settings(a);
  const MethodChoice other = used_settings(b);
  return method == other.method && tolerance == other.tolerance &&
         relative_error == other.relative_error && lights_per_point == other.lights_per_point &&
         rt_fallback == other.rt_fallback;
}

bool operator!=(const MethodChoice& a, const MethodChoice& b) {
  return !(a == b);
}

}  // namespace lev
