// What a change of the settings restarts (app::restart_needed) is derived from the group that
// changed: the scene choice reloads, the image's size, depth and subsample restart the view, the
// method choice, the threads and the missed-light draws restart the render, the pass count goes
// on, the exposure restarts the render of a method whose images depend on it (the tolerance is in
// displayed units); the rest of the display and a setting the scene or method does not read
// restart nothing. The property test changes every entry of the settings table, so a new setting
// is covered without an edit.
#include <string>

#include <gtest/gtest.h>

#include "app/settings.h"
#include "lev/methods.h"
#include "tests/support/setting_values.h"

namespace {

using app::Restart;

// The settings that only change what the viewer shows of the radiance it holds (the display
// curve, and the exposure for a method that does not read the display scale) or its sizing rule
// (which sets the width and height, compared themselves).
bool display_only(const std::string& setting, const lev::MethodInfo& method) {
  if (setting == "exposure") return !method.reads_display_scale;
  return setting == "display" || setting == "resolution";
}

Restart restart_after(const app::Settings& before, void (*change)(app::Settings&)) {
  app::Settings after = before;
  change(after);
  return app::restart_needed(before, after);
}

TEST(Restart, EachGroupRestartsWhatItFeeds) {
  const app::Settings s;
  EXPECT_EQ(app::restart_needed(s, s), Restart::nothing);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.scene.name = "maze"; }), Restart::scene);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.scene.level += 1; }), Restart::scene);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.scene.camera_flags.vertical_fov_deg = 20; }),
            Restart::scene);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.width += 1; }), Restart::view);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.depth += 1; }), Restart::view);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.subsample += 1; }), Restart::view);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.threads += 1; }), Restart::render);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.missed_draws = 16; }), Restart::render);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.image.spp += 1; }), Restart::passes);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.method.method = lev::Method::rt; }),
            Restart::render);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.method.tolerance = 0.5; }), Restart::render);
  // lev culls at the tolerance / 2^EV: another exposure is another image of it.
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.display.exposure_ev = 2.0; }),
            Restart::render);
  // The auto flag alone: the EV it chose is exposure_ev, compared by itself.
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.display.exposure_auto = true; }),
            Restart::nothing);
  EXPECT_EQ(
      restart_after(s, [](app::Settings& a) { a.display.curve = renderer::DisplayCurve::srgb; }),
      Restart::nothing);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.resolution = "fit/2"; }), Restart::nothing);
}

TEST(Restart, TheLargestChangeWins) {
  const app::Settings s;
  EXPECT_EQ(restart_after(s,
                          [](app::Settings& a) {
                            a.image.spp += 1;
                            a.method.tolerance = 0.5;
                            a.image.width += 1;
                          }),
            Restart::view);
  EXPECT_EQ(restart_after(s,
                          [](app::Settings& a) {
                            a.image.width += 1;
                            a.scene.level += 1;
                          }),
            Restart::scene);
}

TEST(Restart, WhatTheSceneOrMethodDoesNotReadRestartsNothing) {
  app::Settings s;
  // A built-in scene has one preset camera: its index changes nothing (the rt reference stays).
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.scene.camera = 3; }), Restart::nothing);
  s.scene.name = "room.gltf";
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.scene.camera = 3; }), Restart::scene);
  s = app::Settings{};
  s.method.method = lev::Method::rt;
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.method.tolerance = 0.5; }), Restart::nothing);
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.method.lights_per_point = 4; }),
            Restart::nothing);
  // rt's radiance does not depend on the exposure: the viewer re-maps it.
  EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.display.exposure_ev = 2.0; }),
            Restart::nothing);
}

// The methods whose images depend on the exposure: those with a tolerance (in displayed units)
// and lev_cut (its drop is one displayed 8-bit step); not rt, the samplers without a tolerance or
// lightcuts (relative to the point's own total).
TEST(Restart, TheExposureRestartsTheMethodsThatReadTheDisplayScale) {
  for (const lev::MethodInfo& method : lev::method_table()) {
    app::Settings s;
    s.method.method = method.id;
    const bool reads = method.uses_tolerance || method.id == lev::Method::lev_cut;
    EXPECT_EQ(method.reads_display_scale, reads) << method.name;
    EXPECT_EQ(restart_after(s, [](app::Settings& a) { a.display.exposure_ev = -1.5; }),
              reads ? Restart::render : Restart::nothing)
        << method.name;
    // A curve of its own, or an EV no float tells from the current one, changes no image.
    EXPECT_EQ(restart_after(s,
                            [](app::Settings& a) {
                              a.display.curve = renderer::DisplayCurve::neutral;
                              a.display.exposure_ev = 1e-12;
                            }),
              Restart::nothing)
        << method.name;
  }
}

// Every table entry, changed to another valid value with every method current: a setting the
// table calls unused restarts nothing, a display setting restarts nothing, and every other
// setting restarts something. A setting added to a group and the table is checked here as is.
TEST(Restart, EverySettingOfTheTableRestartsUnlessUnusedOrDisplayOnly) {
  int restarting = 0, quiet = 0;
  for (const lev::MethodInfo& method : lev::method_table()) {
    app::Settings base;
    base.method.method = method.id;
    for (const app::SettingSpec& spec : app::setting_table()) {
      const std::string value = levrt_test::other_setting_value(base, spec);
      ASSERT_FALSE(value.empty()) << spec.name << ": no other valid value";
      app::Settings changed = base;
      app::set_setting(changed, spec, value);
      const Restart restart = app::restart_needed(base, changed);
      const bool unused = spec.unused_because && spec.unused_because(base) != nullptr;
      if (unused || display_only(spec.name, method)) {
        EXPECT_EQ(restart, Restart::nothing)
            << spec.name << "=" << value << " with " << method.name;
        ++quiet;
      } else {
        EXPECT_NE(restart, Restart::nothing)
            << spec.name << "=" << value << " with " << method.name;
        ++restarting;
      }
    }
  }
  EXPECT_GT(restarting, 0);
  EXPECT_GT(quiet, 0);
}

}  // namespace
