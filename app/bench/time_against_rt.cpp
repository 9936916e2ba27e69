#include "app/bench/time_against_rt.h"

#include <cstdio>

#include "app/bench/experiment_support.h"

namespace app::bench {
namespace {

// Above this share of rt's lights the shadow rays are nearly rt's, so the excess is the walk.
constexpr double kMostLights = 0.5;

}  // namespace

std::optional<SlowerThanRt> check_time_against_rt(const std::string& scene,
                                                  const std::string& method, double setting,
                                                  double seconds, double rt_seconds,
                                                  double lights_tested, double rt_lights_tested) {
  // NaN compares false: a render not measured is not listed.
  if (!(seconds > kMaxTimeOverRt * rt_seconds) || !(rt_seconds > 0.0)) return std::nullopt;
  SlowerThanRt slower{scene, method, setting, seconds / rt_seconds, 0.0};
  slower.lights_tested_share = rt_lights_tested > 0.0 ? lights_tested / rt_lights_tested : 0.0;
  return slower;
}

std::string slower_text(const SlowerThanRt& s) {
  char head[160];
  std::snprintf(head, sizeof head, "%s %s %s: %.2fx rt's time; it tests %.0f %% of rt's lights",
                s.scene.c_str(), s.method.c_str(), tolerance_text(s.setting).c_str(),
                s.time_over_rt, 100.0 * s.lights_tested_share);
  const char* why =
      s.shaded_with_rt
          ? " per point: it shaded with rt's loop (its probe chose rt), so the excess is the "
            "probe, the method's set-up or the machine's noise"
      : s.lights_tested_share >= 1.0
          ? " per point or more (clusters of lights rt skips as unlit): its walk or cut saves no "
            "shadow ray and is all overhead"
      : s.lights_tested_share >= kMostLights
          ? " per point: its culling admits most lights, so its walk comes on top of rt's shadow "
            "rays"
          : " per point, and its walk and clusters cost more than the shadow rays it saves";
  return head + std::string(why);
}

}  // namespace app::bench
