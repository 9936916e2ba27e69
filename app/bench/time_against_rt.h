// The bench's check that no deterministic method costs more than rt: a method whose culling
// admits most lights must not pay its walk on top of rt's shadow rays. A render of a
// deterministic method at more than kMaxTimeOverRt times rt's time (both made in turns on the
// same pixels) is listed with the reason the numbers give: the share of rt's lights per point it
// still shadow-tests (all of them or more, counting clusters of lights rt skips as unlit: its
// walk or cut is all overhead; most of them: its culling admits nearly everything, so its walk
// comes on top of rt's rays), or, when it tests far fewer, that its walk and clusters cost more
// than the shadow rays it saves. The targets experiment prints each one.
#pragma once

#include <optional>
#include <string>

namespace app::bench {

inline constexpr double kMaxTimeOverRt = 1.1;

struct SlowerThanRt {
  std::string scene;  // as the tables name it, light count included
  std::string method;
  double setting = 0.0;
  double time_over_rt = 0.0;         // the method's CPU time over rt's
  double lights_tested_share = 0.0;  // its shadow-tested lights per point over rt's
  // It shaded with rt's loop (renderer/rt_fallback.h): the excess is then the probe that chose
  // so, its set-up, or the machine's noise.
  bool shaded_with_rt = false;
};

// The render when it took more than kMaxTimeOverRt times rt's time; nothing when it did not, or
// when a time is not a number (a render not measured).
std::optional<SlowerThanRt> check_time_against_rt(const std::string& scene,
                                                  const std::string& method, double setting,
                                                  double seconds, double rt_seconds,
                                                  double lights_tested, double rt_lights_tested);

// One line: "stage 4,608 lev_bounded 0.001: 1.32x rt's time; it tests 97 % of rt's lights per
// point: its culling admits nearly every light, so its walk comes on top of rt's shadow rays".
std::string slower_text(const SlowerThanRt& slower);

}  // namespace app::bench
