// The viewer's pure parts: camera moves, scripted changes, the UI-side image and its pixel
// errors, the trade plot's points and the frame report.
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "app/render_command.h"
#include "app/viewer/camera_control.h"
#include "app/viewer/display_image.h"
#include "app/viewer/frame_log.h"
#include "app/viewer/inspector_panel.h"
#include "app/viewer/live_stats.h"
#include "app/viewer/scripted_changes.h"
#include "app/viewer/settings_panel.h"
#include "app/viewer/snapshot_panel.h"
#include "app/viewer/trade_plot.h"
#include "renderer/framebuffer.h"
#include "tests/support/temp_dir.h"

namespace {
using namespace app::viewer;
using app::parse_view_mode;
using app::view_info;
using app::ViewMode;
using app::ViewPixels;

renderer::Camera test_camera() {
  renderer::Camera c;
  c.position = {3.0f, -8.0f, 5.0f};
  c.target = {1.0f, 2.0f, 0.5f};
  c.up = {0.0f, 0.0f, 1.0f};
  return c;
}

TEST(CameraControl, OrbitKeepsTheTargetAndTheDistance) {
  const renderer::Camera c = test_camera();
  const renderer::Camera o = orbit_camera(c, 0.7f, 0.3f);
  EXPECT_EQ(o.target, c.target);
  EXPECT_NEAR(glm::length(o.position - o.target), glm::length(c.position - c.target), 1e-4f);
  EXPECT_GT(glm::length(o.position - c.position), 0.1f);
  // Pitch raises the eye; it never passes over the pole.
  EXPECT_GT(orbit_camera(c, 0.0f, 0.2f).position.z, c.position.z);
  const renderer::Camera top = orbit_camera(c, 0.0f, 10.0f);
  const glm::vec3 dir = glm::normalize(top.position - top.target);
  EXPECT_LT(dir.z, 1.0f);
  EXPECT_GT(std::acos(dir.z), 0.01f);
}

TEST(CameraControl, YawTurnsAboutTheUpAxis) {
  const renderer::Camera c = test_camera();
  const renderer::Camera o = orbit_camera(c, 1.0f, 0.0f);
  EXPECT_NEAR(o.position.z, c.position.z, 1e-4f);
  const renderer::Camera back = orbit_camera(o, -1.0f, 0.0f);
  EXPECT_NEAR(glm::length(back.position - c.position), 0.0f, 1e-4f);
}

TEST(CameraControl, PanMovesEyeAndTargetTogether) {
  const renderer::Camera c = test_camera();
  const renderer::Camera p = pan_camera(c, 0.25f, -0.5f);
  EXPECT_NEAR(glm::length((p.position - c.position) - (p.target - c.target)), 0.0f, 1e-4f);
  EXPECT_GT(glm::length(p.target - c.target), 0.1f);
  // A full image height of pan moves by the visible height at the target.
  const float distance = glm::length(c.target - c.position);
  const float visible = 2.0f * distance * std::tan(glm::radians(c.vertical_fov_deg) * 0.5f);
  EXPECT_NEAR(glm::length(pan_camera(c, 0.0f, 1.0f).target - c.target), visible, 1e-3f);
}

TEST(CameraControl, ZoomScalesTheDistance) {
  const renderer::Camera c = test_camera();
  const float d = glm::length(c.position - c.target);
  EXPECT_NEAR(glm::length(zoom_camera(c, 0.5f).position - c.target), 0.5f * d, 1e-4f);
  EXPECT_EQ(zoom_camera(c, 0.5f).target, c.target);
  EXPECT_GT(glm::length(zoom_camera(c, 0.0f).position - c.target), 0.0f);
}

// No wheel, drag or pan takes the camera past the camera flags' bound (1e6): some 300 wheel
// notches out used to put the eye past 1.8e18, where Embree asserts (the viewer died, SIGABRT).
TEST(CameraControl, NoMoveLeavesTheCameraBound) {
  renderer::Camera c = test_camera();
  for (int i = 0; i < 1000; ++i) c = zoom_camera(c, 1.0f / 0.88f);
  EXPECT_TRUE(camera_within_bounds(c));
  EXPECT_GT(glm::length(c.position - c.target), 1e5f) << "the zoom goes out to the bound";
  EXPECT_EQ(c.target, test_camera().target);
  for (int i = 0; i < 100; ++i) c = orbit_camera(c, 0.3f, 0.05f);
  EXPECT_TRUE(camera_within_bounds(c));
  // Back in, the zoom works as before.
  for (int i = 0; i < 1000; ++i) c = zoom_camera(c, 0.88f);
  EXPECT_NEAR(glm::length(c.position - c.target), 1e-3f, 1e-4f);
  for (int i = 0; i < 1000; ++i) c = pan_camera(zoom_camera(c, 1e4f), 0.7f, 0.4f);
  EXPECT_TRUE(camera_within_bounds(c));
  renderer::Camera ortho = test_camera();
  ortho.orthographic_half_height = 10.0f;
  for (int i = 0; i < 1000; ++i) ortho = zoom_camera(ortho, 2.0f);
  EXPECT_TRUE(camera_within_bounds(ortho));
  EXPECT_GT(ortho.orthographic_half_height, 1e5f);
}

TEST(ScriptedChanges, ParseValidChanges) {
  const ScriptedChange a = parse_scripted_change("tolerance=0.1@12");
  EXPECT_EQ(a.key, "tolerance");
  EXPECT_EQ(a.value, "0.1");
  EXPECT_EQ(a.frame, 12);
  EXPECT_EQ(parse_scripted_change("screenshot=/tmp/a@b.png@3").value, "/tmp/a@b.png");
  for (const char* ok :
       {"method=rt@0", "lights=256@5", "view=error@7", "reference=off@1", "await=idle@2",
        "snapshot=out@9", "hover=10,20@4", "width=64@1", "memory=report@6", "scene=maze@3"}) {
    EXPECT_NO_THROW(parse_scripted_change(ok)) << ok;
  }
}

TEST(ScriptedChanges, RejectMalformedChanges) {
  for (const char* bad :
       {"tolerance=0.1", "tolerance@3", "=1@2", "tolerance=-1@3", "method=foo@1", "view=x@1",
        "colour=red@1", "lights=-4@1", "lights=abc@1", "reference=maybe@1", "await=soon@1",
        "width=0@1", "tolerance=0.1@-1", "tolerance=0.1@x", "hover=1@2", "snapshot=@1",
        "memory=peak@1", "scene=nowhere@1"}) {
    EXPECT_THROW(parse_scripted_change(bad), app::UsageError) << bad;
  }
}

// A script's numbers take the settings' decimal grammar, as every flag does: no '+', no space,
// no hex, in the frame, a pixel, a window size, the swipe and the mask threshold.
TEST(ScriptedChanges, NumbersTakeOnlyPlainDecimals) {
  for (const char* bad :
       {"tolerance=0.1@+3", "tolerance=0.1@ 3", "tolerance=0.1@0x3", "hover=+1,2@1", "hover=1, 2@1",
        "hover= 1,2@1", "hover=0x1,2@1", "swipe=+0.5@1", "swipe= 0.5@1", "swipe=0x1p-1@1",
        "mask_threshold=+2@1", "mask_threshold=0x2@1", "inspect=+1,2@1"}) {
    EXPECT_THROW(parse_scripted_change(bad), app::UsageError) << bad;
  }
  for (const char* ok : {"tolerance=0.1@3", "hover=1,2@1", "swipe=0.5@1", "swipe=.5@1",
                         "mask_threshold=2e0@1", "inspect=1,2@1"}) {
    EXPECT_NO_THROW(parse_scripted_change(ok)) << ok;
  }
  int w = 0, h = 0;
  EXPECT_TRUE(app::viewer::parse_window_size("800x600", w, h));
  EXPECT_FALSE(app::viewer::parse_window_size("800x+600", w, h));
  EXPECT_FALSE(app::viewer::parse_window_size(" 800x600", w, h));
  EXPECT_FALSE(app::viewer::parse_window_size("0x320x600", w, h));
}

TEST(ScriptedChanges, AFrameOutOfRangeIsRefusedNamingTheRange) {
  for (const char* bad : {"tolerance=0.1@99999999999", "tolerance=0.1@100000001"}) {
    try {
      parse_scripted_change(bad);
      FAIL() << bad << " was accepted";
    } catch (const app::UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("a whole number from 0 to 100000000"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(parse_scripted_change("tolerance=0.1@100000000").frame, 100000000);
}

TEST(ScriptedChanges, ARenamedKeyNamesItsNewName) {
  try {
    parse_scripted_change("samples=4@2");
    FAIL() << "samples=4@2 was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("samples is now called lights-per-point"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(parse_scripted_change("lights-per-point=4@2").value, "4");
}

TEST(ScriptedChanges, AScriptFileGivesItsLinesAndAMissingOneIsAUsageError) {
  const levrt_test::TempDir temp("levrt_script_file_");
  const std::string path = (temp.path() / "changes.txt").string();
  std::ofstream(path) << "method=ast@1\n\nmemory=report@2\n";
  EXPECT_EQ(read_script_file(path), (std::vector<std::string>{"method=ast@1", "memory=report@2"}));
  EXPECT_THROW(read_script_file((temp.path() / "missing.txt").string()), app::UsageError);
}

TEST(ScriptedChanges, ABadScriptLineIsNamedByItsFileAndLineNumber) {
  const levrt_test::TempDir temp("levrt_script_line_");
  const std::string path = (temp.path() / "changes.txt").string();
  std::ofstream(path) << "method=ast@1\r\n\nlights=-4@2\n";
  try {
    read_script_file(path);
    FAIL() << "lights=-4@2 was accepted";
  } catch (const app::UsageError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("--script: " + path + " line 3: ", 0), 0u) << what;
    EXPECT_NE(what.find("lights=-4@2"), std::string::npos) << what;
  }
  // A line saved with CRLF reads as its text.
  std::ofstream(path) << "method=ast@1\r\n";
  EXPECT_EQ(read_script_file(path), std::vector<std::string>{"method=ast@1"});
}

TEST(ScriptedChanges, WhatTheRunningScriptWouldFailAtIsRefusedBeforeItRuns) {
  const app::Settings initial;  // building at its default level
  const auto refusal = [&](const std::vector<std::string>& texts, int frames) {
    try {
      check_script(parse_scripted_changes(texts), initial, frames);
    } catch (const app::UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // A light count the scene at that frame lacks, also after a change of scene.
  EXPECT_NE(refusal({"screenshot=a.png@1", "lights=65@3"}, 0).find("got 'lights=65@3'"),
            std::string::npos);
  EXPECT_EQ(refusal({"lights=65536@1"}, 0), "");
  EXPECT_NE(refusal({"lights=45@2"}, 0), "");
  EXPECT_EQ(refusal({"scene=maze@1", "lights=45@2"}, 0), "");
  EXPECT_NE(refusal({"scene=maze@3", "lights=45@2"}, 0), "");
  EXPECT_NE(refusal({"scene=maze@1", "scene=hall@1", "lights=45@2"}, 0), "");
  EXPECT_NE(refusal({"scene=x.json@1", "lights=64@2"}, 0).find("scene file"), std::string::npos);
  EXPECT_NE(refusal({"drop=x.gltf@1", "lights=64@2"}, 0), "");
  EXPECT_THROW(parse_scripted_change("lights= -1@3"), app::UsageError);
  EXPECT_THROW(parse_scripted_change("lights=+64@3"), app::UsageError);
  // A frame the session never reaches.
  const std::string late = refusal({"screenshot=late.png@10"}, 3);
  EXPECT_NE(late.find("past the last frame"), std::string::npos) << late;
  EXPECT_NE(late.find("screenshot=late.png@10"), std::string::npos) << late;
  EXPECT_NE(refusal({"tolerance=0.1@3"}, 3), "");
  EXPECT_EQ(refusal({"tolerance=0.1@2"}, 3), "");
  EXPECT_EQ(refusal({"screenshot=late.png@10"}, 0), "") << "--frames 0 runs until closed";
  // Settings a render refuses: one missed-light draw, a typed size over the memory budget.
  EXPECT_NE(refusal({"missed-draws=1@1"}, 0).find("--missed-draws"), std::string::npos);
  EXPECT_EQ(refusal({"missed-draws=2@1"}, 0), "");
  EXPECT_NE(refusal({"width=16384@1", "height=16384@2"}, 0).find("height=16384@2"),
            std::string::npos);
  EXPECT_EQ(refusal({"width=4096@1", "height=4096@2"}, 0), "");
  // A flag's own bad value is named by the flag, not blamed on the first change.
  app::Settings one_draw;
  one_draw.image.missed_draws = 1;
  try {
    check_script(parse_scripted_changes({"tolerance=0.1@1"}), one_draw, 0);
    FAIL() << "--missed-draws 1 was accepted";
  } catch (const app::UsageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--missed-draws: ", 0), 0u) << e.what();
    EXPECT_EQ(std::string(e.what()).find("tolerance=0.1@1"), std::string::npos) << e.what();
  }
}

TEST(ScriptedChanges, ResidentMemoryGrowsWithTouchedMemory) {
  const std::uint64_t before = current_resident_bytes();
  ASSERT_GT(before, 0u);
  const std::vector<char> block(std::size_t{64} << 20, 1);  // 64 MiB written, so resident
  EXPECT_GE(current_resident_bytes(), before + (std::uint64_t{60} << 20)) << int{block.back()};
}

TEST(ScriptedChanges, AHoverOutsideTheImageAtItsFrameIsRefused) {
  app::Settings initial;
  initial.resolution = "typed";
  initial.image.width = 64;
  initial.image.height = 48;
  const auto check = [&](const std::vector<std::string>& texts) {
    check_script(parse_scripted_changes(texts), initial, 0);
  };
  EXPECT_NO_THROW(check({"hover=63,47@3"}));
  // So is a pixel pinned in the inspector, which would wait for an inspection forever.
  EXPECT_THROW(check({"inspect=64,10@3"}), app::UsageError);
  EXPECT_NO_THROW(check({"inspect=63,47@3", "inspect=off@4"}));
  EXPECT_THROW(check({"hover=64,10@3"}), app::UsageError);
  EXPECT_THROW(check({"hover=10,48@3"}), app::UsageError);
  // The size in effect at the hover's frame counts: a later change does not, an earlier one
  // (or one before it in the same frame) does.
  EXPECT_NO_THROW(check({"width=200@2", "hover=150,10@3", "width=32@4"}));
  EXPECT_THROW(check({"hover=150,10@3", "width=200@4"}), app::UsageError);
  EXPECT_NO_THROW(check({"width=200@3", "hover=150,10@3"}));
  EXPECT_THROW(check({"hover=150,10@3", "width=200@3"}), app::UsageError);
  try {
    check({"hover=100,10@3"});
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("64x48"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("image pixels"), std::string::npos) << e.what();
  }
}

TEST(ScriptedChanges, ApplyChangesTheState) {
  ViewerState s;
  s.request_dirty = false;
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("tolerance=0.25@0")),
            ScriptAction::none);
  EXPECT_DOUBLE_EQ(s.settings.method.tolerance, 0.25);
  EXPECT_TRUE(s.request_dirty);
  apply_scripted_change(s, parse_scripted_change("lights=4096@0"));
  EXPECT_EQ(s.settings.scene.level, 6);
  apply_scripted_change(s, parse_scripted_change("view=error@0"));
  EXPECT_EQ(s.view, ViewMode::error);
  EXPECT_TRUE(s.want_reference);
  // A count the scene lacks (check_script refuses those it can know) is logged and changes nothing.
  s.request_dirty = false;
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("lights=100@0")), ScriptAction::none);
  EXPECT_EQ(s.settings.scene.level, 6);
  EXPECT_FALSE(s.request_dirty);
  ASSERT_FALSE(s.messages.empty());
  EXPECT_TRUE(s.messages.back().problem);
  EXPECT_NE(s.messages.back().text.find("lights=100"), std::string::npos) << s.messages.back().text;
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("await=idle@0")),
            ScriptAction::await_idle);
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("screenshot=a.png@0")),
            ScriptAction::screenshot);
}

// The relative error's 0 button said "tolerance 0: no culling" (the tolerance's tooltip) on hover.
TEST(SettingsPanel, EachZeroButtonsTooltipNamesItsOwnSetting) {
  EXPECT_EQ(zero_button_tooltip(*app::find_setting("tolerance")).rfind("tolerance 0", 0), 0u);
  const std::string relative = zero_button_tooltip(*app::find_setting("relative-error"));
  EXPECT_EQ(relative.rfind("relative-error 0", 0), 0u) << relative;
  EXPECT_EQ(relative.find("tolerance"), std::string::npos) << relative;
}

// A value typed outside the setting's range (a relative error of 5) was dropped without a word.
TEST(SettingsPanel, AValueTypedOutsideItsRangeIsNamedWhyItIsRefused) {
  const app::SettingSpec& relative = *app::find_setting("relative-error");
  const auto& range = std::get<app::RealRange>(relative.kind);
  EXPECT_EQ(typed_value_refusal(relative, range, 0.05), "");
  const std::string refused = typed_value_refusal(relative, range, 5.0);
  EXPECT_EQ(refused.rfind("relative-error: must be in [0, 1], got 5", 0), 0u) << refused;
  EXPECT_NE(typed_value_refusal(relative, range, -1.0), "");
}

TEST(SettingsPanel, ANumberFieldStepsOverTheValuesARenderRefuses) {
  const app::SettingSpec& draws = *app::find_setting("missed-draws");
  const auto& range = std::get<app::IntRange>(draws.kind);
  EXPECT_EQ(panel_int_value(draws, range, 0, 1), 2) << "'+' from off";
  EXPECT_EQ(panel_int_value(draws, range, 2, 1), 0) << "'-' from the fewest draws";
  EXPECT_EQ(panel_int_value(draws, range, 2, 3), 3);
  EXPECT_EQ(panel_int_value(draws, range, 0, 100000), range.max);
  EXPECT_EQ(panel_int_value(draws, range, 0, -5), 0);
  const app::SettingSpec& depth = *app::find_setting("depth");
  const auto& depth_range = std::get<app::IntRange>(depth.kind);
  EXPECT_EQ(panel_int_value(depth, depth_range, 0, 1), 1);
  EXPECT_EQ(panel_int_value(depth, depth_range, 64, 65), 64);
}

TEST(InspectorPanel, APinnedPixelOutsideTheImageSaysSoInsteadOfInspectingForever) {
  ViewerState s;
  EXPECT_EQ(inspector_wait_text(s), "");
  s.status.width = 32;
  s.status.height = 24;
  s.inspect_pixel = std::array<int, 2>{31, 23};
  EXPECT_EQ(inspector_wait_text(s), "inspecting...");
  s.inspect_pixel = std::array<int, 2>{100, 10};  // pinned before the window shrank
  EXPECT_NE(inspector_wait_text(s).find("outside the 32x24 image"), std::string::npos)
      << inspector_wait_text(s);
}

// A fit resolution renders what the window's image area holds: within the memory budget at any
// window size, so a huge window shows the picture enlarged instead of failing the render (before:
// `view --window 16000x12000` exited 2 naming --width/--height, which were never given).
// The stats panel named lev_cut, lightcuts and rt as ignoring the tolerance and showed no relative
// error, and said "lev_cut walks no light hierarchy" where the rt fallback shaded with rt's loop.
TEST(LiveStats, TheMethodRowNamesWhatItsMethodReadsAndNoNodesSaysWhy) {
  lev::MethodChoice choice;
  choice.tolerance = 0.03;
  choice.relative_error = 0.005;
  choice.lights_per_point = 4;
  choice.method = lev::Method::lev;
  EXPECT_EQ(method_text(choice), "lev, tolerance 0.03");
  choice.method = lev::Method::lev_cut;
  EXPECT_EQ(method_text(choice), "lev_cut, relative error 0.005");
  choice.method = lev::Method::rt;
  EXPECT_EQ(method_text(choice), "rt");
  choice.method = lev::Method::light_tree;
  EXPECT_EQ(method_text(choice), "light_tree, 4 lights per point");
  EXPECT_EQ(nodes_visited_text(0.0, 100, "lev_cut", true), "none (shaded with rt's loop)");
  EXPECT_EQ(nodes_visited_text(0.0, 100, "ast", false), "none (ast walks no light hierarchy)");
  EXPECT_EQ(nodes_visited_text(12.5, 100, "lev", false), "12.50 avg");
  EXPECT_EQ(nodes_visited_text(0.0, 0, "lev", false), "0.00 avg");
}

// Snapshot names carried the tolerance whatever the method: lev_cut at two relative errors had one
// name (told apart only by _2), rt a tolerance it ignores.
TEST(SnapshotName, NamesTheSettingItsMethodReads) {
  lev::MethodChoice choice;
  choice.tolerance = 0.01;
  choice.relative_error = 0.005;
  choice.lights_per_point = 8;
  choice.method = lev::Method::lev;
  EXPECT_EQ(snapshot_base_name("building", 64, choice), "view_building_64_lev_0.01");
  choice.method = lev::Method::lev_cut;
  EXPECT_EQ(snapshot_base_name("hall", 4096, choice), "view_hall_4096_lev_cut_0.005");
  choice.method = lev::Method::rt;
  EXPECT_EQ(snapshot_base_name("my scene/x", 3, choice), "view_my_scene_x_3_rt");
  choice.method = lev::Method::lev_mc;
  EXPECT_EQ(snapshot_base_name("hall", 64, choice), "view_hall_64_lev_mc_0.01_k8");
  choice.lights_per_point = 1;
  EXPECT_EQ(snapshot_base_name("hall", 64, choice), "view_hall_64_lev_mc_0.01");
}

TEST(ViewerState, AFitSizeStaysWithinTheMemoryBudgetAtAnyWindowSize) {
  EXPECT_EQ(fit_render_size(1000, 800, 2), (std::array<int, 2>{500, 400}));
  EXPECT_EQ(fit_render_size(0, -3, 1), (std::array<int, 2>{1, 1}));
  const std::array<int, 2> big = fit_render_size(15562, 7992, 1);
  app::Settings settings;
  settings.image.width = big[0];
  settings.image.height = big[1];
  EXPECT_NO_THROW(app::check_memory_budget(settings, true)) << big[0] << "x" << big[1];
  EXPECT_GT(big[0], 8000);
  EXPECT_NEAR(static_cast<double>(big[0]) / big[1], 15562.0 / 7992.0, 1e-3);
}

// A typed size whose image fits the memory budget but whose rt reference (a second framebuffer)
// does not: the render worker renders the image and says why the reference is not rendered (it
// checked the size with the reference and failed the whole render). The worker's two checks,
// image alone and with the reference, are memory_budget_refusal's.
TEST(ViewerState, ASizeThatFitsOnlyWithoutTheReferenceIsRefusedTheReferenceAlone) {
  app::Settings settings;
  settings.image.width = 7000;
  settings.image.height = 7000;
  EXPECT_EQ(app::memory_budget_refusal(settings, false), "");
  const std::string refusal = app::memory_budget_refusal(settings, true);
  EXPECT_NE(refusal.find("7000x7000 with --reference needs about 11962 MiB"), std::string::npos)
      << refusal;
  EXPECT_THROW(app::check_memory_budget(settings, true), app::UsageError);
  EXPECT_NO_THROW(app::check_memory_budget(settings, false));
  settings.image.width = 9000;
  EXPECT_NE(app::memory_budget_refusal(settings, false), "");
}

TEST(ViewerState, ATypedSizeLeavesTheFitResolutionAndAFitSizeKeepsIt) {
  ViewerState s;
  EXPECT_EQ(s.settings.resolution, "fit");
  s.want_reference = true;
  set_fit_size(s, 500, 300);
  EXPECT_EQ(s.settings.resolution, "fit");
  EXPECT_TRUE(s.want_reference);
  EXPECT_EQ(s.settings.image.width, 500);
  EXPECT_TRUE(s.request_dirty);
  const app::Settings before = s.settings;
  s.settings.image.width = 200;
  settings_changed(s, before, "width");
  EXPECT_EQ(s.settings.resolution, "typed");
  // Choosing a fit scale with the size unchanged keeps it.
  const app::Settings typed = s.settings;
  s.settings.resolution = "fit/2";
  settings_changed(s, typed, "resolution");
  EXPECT_EQ(s.settings.resolution, "fit/2");
  EXPECT_EQ(app::fit_divisor("fit/4"), 4);
  EXPECT_EQ(app::fit_divisor("typed"), 0);
}

TEST(ScriptedChanges, HoversAreCheckedOnlyAgainstTypedSizesAndWindowSizesParse) {
  app::Settings initial;  // fit: the size follows the window
  EXPECT_NO_THROW(check_script(parse_scripted_changes({"hover=900,700@3"}), initial, 0));
  EXPECT_THROW(check_script(parse_scripted_changes({"width=100@1", "hover=900,70@3"}), initial, 0),
               app::UsageError);
  EXPECT_NO_THROW(check_script(
      parse_scripted_changes({"width=100@1", "resolution=fit@2", "hover=900,70@3"}), initial, 0));
  ViewerState s;
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("window=900x700@1")),
            ScriptAction::resize_window);
  EXPECT_EQ(apply_scripted_change(s, parse_scripted_change("await=preview@1")),
            ScriptAction::await_preview);
  EXPECT_THROW(parse_scripted_change("window=100x100@1"), app::UsageError);
  EXPECT_THROW(parse_scripted_change("window=big@1"), app::UsageError);
  int w = 0, h = 0;
  EXPECT_TRUE(parse_window_size("1024x640", w, h));
  EXPECT_EQ(w, 1024);
  EXPECT_EQ(h, 640);
}

// The Missed light view asks for the estimate where the method makes one; ast, lightcuts and
// lev_cut do not (their estimate would read 0 where their pixels differ from rt's).
TEST(ViewerState, TheMissedLightViewTurnsTheEstimateOnOnlyForMethodsThatMakeIt) {
  ViewerState s;
  select_view(s, ViewMode::missed);
  for (const lev::MethodInfo& method : lev::method_table()) {
    s.settings.method.method = method.id;
    const int draws = make_request(s).settings.image.missed_draws;
    if (method.missed_light_known) {
      EXPECT_GT(draws, 0) << method.name;
    } else {
      EXPECT_EQ(draws, 0) << method.name;
    }
  }
  s.settings.method.method = lev::Method::lev;
  select_view(s, ViewMode::image);
  EXPECT_EQ(make_request(s).settings.image.missed_draws, 0);
}

TEST(ViewerState, NewSceneResetsTheCameraAndAViewChangeDropsTheReference) {
  ViewerState s;
  s.camera = renderer::Camera{};
  s.want_reference = true;
  app::Settings before = s.settings;
  s.settings.method.tolerance = 0.5;
  settings_changed(s, before, "tolerance");
  EXPECT_TRUE(s.camera.has_value());
  EXPECT_TRUE(s.want_reference);  // same view: the reference stays
  before = s.settings;
  s.settings.scene.level = 4;
  settings_changed(s, before, "level");
  EXPECT_FALSE(s.camera.has_value());
  EXPECT_FALSE(s.want_reference);
}

// A framebuffer with known content, and its tiles as the worker would post them.
renderer::Framebuffer test_framebuffer(int w, int h, float shade, std::uint32_t samples) {
  renderer::Framebuffer f = renderer::make_framebuffer(w, h);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    f.samples[i] = samples;
    f.radiance_sum[i] = glm::vec3(shade * static_cast<float>(i % 7) / 6.0f, shade, 0.25f) *
                        static_cast<float>(samples);
    f.shading_points[i] = 2 * samples;
    f.lights_tested[i] = (i % 5) * samples;
    f.nodes_visited[i] = 10 * samples;
    f.shadow_rays[i] = (i % 5) * samples;
  }
  return f;
}

std::vector<TileUpdate> all_tiles(const renderer::Framebuffer& f, std::uint64_t generation,
                                  int pass, int tile_size) {
  std::vector<TileUpdate> updates;
  int tile = 0;
  for (int y = 0; y < f.height; y += tile_size) {
    for (int x = 0; x < f.width; x += tile_size, ++tile) {
      updates.push_back(
          copy_tile(f, generation, tile, pass,
                    {x, y, std::min(x + tile_size, f.width), std::min(y + tile_size, f.height)}));
    }
  }
  return updates;
}

TEST(ViewerState, ASettingTheSceneDoesNotReadKeepsTheViewAndTheReference) {
  ViewerState s;
  s.camera = renderer::Camera{};
  s.want_reference = true;
  app::Settings before = s.settings;
  s.settings.scene.camera = 2;  // a built-in scene has one preset camera
  settings_changed(s, before, "camera");
  EXPECT_TRUE(s.camera.has_value());
  EXPECT_TRUE(s.want_reference);
  // A glTF file reads it: its new camera is a new scene, with its own preset view.
  s.settings.scene.name = "room.gltf";
  before = s.settings;
  s.camera = renderer::Camera{};
  s.want_reference = true;
  s.settings.scene.camera = 1;
  settings_changed(s, before, "camera");
  EXPECT_FALSE(s.camera.has_value());
  EXPECT_FALSE(s.want_reference);
}

TEST(DisplayImage, TilesRebuildTheFramebuffersColoursAndTotals) {
  const renderer::Framebuffer f = test_framebuffer(37, 21, 0.8f, 3);
  DisplayImage image;
  EXPECT_TRUE(apply_tile_updates(image, all_tiles(f, 5, 2, 8)));
  EXPECT_EQ(image.generation, 5u);
  EXPECT_EQ(image.rgb, renderer::framebuffer_rgb8(f));
  const renderer::FramebufferTotals t = renderer::sum_framebuffer(f);
  const TileTotals s = sum_tile_totals(image);
  EXPECT_EQ(s.samples, t.samples);
  EXPECT_EQ(s.shading_points, t.shading_points);
  EXPECT_EQ(s.lights_tested, t.lights_tested);
  EXPECT_EQ(s.nodes_visited, t.nodes_visited);
  EXPECT_EQ(s.shadow_rays, t.shadow_rays);
  EXPECT_EQ(s.lights_tested_max, t.lights_tested_max);
  EXPECT_EQ(image.tiles_seen, 15);
  EXPECT_FLOAT_EQ(image.lights_tested[3], 3.0f);
}

TEST(DisplayImage, TheNoiseViewShowsEachPixelsStandardErrorFromTheSecondPassOn) {
  renderer::Framebuffer f = renderer::make_framebuffer(4, 3);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    // Pixel i: samples 0.5 and 0.5 + 0.01 i (the first pixel's passes agree, exactly in float).
    const float a = 0.5f, b = 0.5f + 0.01f * static_cast<float>(i);
    f.radiance_sum[i] = glm::vec3(a + b);
    f.radiance_square_sum[i] = glm::vec3(a * a + b * b);
    f.samples[i] = 2;
  }
  DisplayImage image;
  EXPECT_TRUE(apply_tile_updates(image, all_tiles(f, 1, 1, 2)));
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    // Two samples a, b: standard error |a - b| / 2 per channel, three channels, % of 3.
    const double expected = 100.0 * 0.01 * static_cast<double>(i) / 2.0;
    EXPECT_NEAR(image.noise_pct[i], expected, 1e-3 + 1e-3 * expected) << i;
    // The hover read-out shows the same value.
    const std::optional<double> hover =
        view_info(ViewMode::noise).value(view_pixels(image, ErrorImage{}), i);
    ASSERT_TRUE(hover.has_value()) << i;
    EXPECT_FLOAT_EQ(static_cast<float>(*hover), image.noise_pct[i]) << i;
  }
  renderer::HeatmapRange range;
  const std::vector<std::uint8_t> rgb = view_rgb8(image, ErrorImage{}, ViewMode::noise, range);
  EXPECT_EQ(range.min, 0.0);
  EXPECT_NEAR(range.max, image.noise_pct.back(), 1e-9);
  EXPECT_NE(std::vector<std::uint8_t>(rgb.begin(), rgb.begin() + 3),
            std::vector<std::uint8_t>(rgb.end() - 3, rgb.end()));
  // One sample: no spread known, the pixels show as not yet rendered.
  f.samples.assign(f.samples.size(), 1);
  DisplayImage single;
  apply_tile_updates(single, all_tiles(f, 2, 0, 2));
  view_rgb8(single, ErrorImage{}, ViewMode::noise, range);
  EXPECT_EQ(range.max, 0.0);
  EXPECT_FALSE(view_info(ViewMode::noise).value(view_pixels(single, ErrorImage{}), 2 * 4 + 3));
  EXPECT_EQ(parse_view_mode("noise"), ViewMode::noise);
}

TEST(DisplayImage, OlderGenerationsAreDroppedAndNewerOnesKeepADimmedBackdrop) {
  DisplayImage image;
  apply_tile_updates(image, all_tiles(test_framebuffer(16, 16, 0.8f, 1), 3, 0, 8));
  EXPECT_FALSE(apply_tile_updates(image, all_tiles(test_framebuffer(16, 16, 0.1f, 1), 2, 0, 8)));
  const std::vector<std::uint8_t> before = image.rgb;
  std::vector<TileUpdate> next = all_tiles(test_framebuffer(16, 16, 0.1f, 1), 4, 0, 8);
  next.resize(1);  // only the first tile of the new render so far
  EXPECT_TRUE(apply_tile_updates(image, next));
  EXPECT_EQ(image.generation, 4u);
  EXPECT_EQ(image.samples[0], 1u);
  EXPECT_EQ(image.samples[15 * 16 + 15], 0u);
  renderer::HeatmapRange range;
  const std::vector<std::uint8_t> shown = view_rgb8(image, ErrorImage{}, ViewMode::image, range);
  const std::size_t stale = 3 * (15 * 16 + 15);
  EXPECT_EQ(image.rgb[stale], before[stale]);
  EXPECT_LT(shown[stale + 1], before[stale + 1]);  // dimmed
}

// Each pixel compares the two means over the same passes: all of them when both have as many,
// else the first 2^L both have (a reference ahead of a method that started again).
TEST(DisplayImage, ErrorAgainstTheReferenceComparesTheSamePasses) {
  DisplayImage image, reference;
  const renderer::Framebuffer pass0 = test_framebuffer(16, 8, 0.5f, 1);
  apply_tile_updates(reference, all_tiles(pass0, 7, 0, 8));
  apply_tile_updates(image, all_tiles(pass0, 9, 0, 8));
  ErrorImage e = compute_error_image(image, reference, 1.0f);
  EXPECT_EQ(e.pixels_compared, 128u);
  EXPECT_EQ(e.pixels_rendered, 128u);
  EXPECT_EQ(e.passes, 1);
  EXPECT_DOUBLE_EQ(e.max_pct, 0.0);
  // The image's second pass while the reference has one: pass 0 against pass 0.
  const renderer::Framebuffer two = test_framebuffer(16, 8, 0.9f, 2);
  apply_tile_updates(image, all_tiles(two, 9, 1, 8));
  e = compute_error_image(image, reference, 1.0f);
  EXPECT_EQ(e.passes, 1);
  EXPECT_DOUBLE_EQ(e.max_pct, 0.0);
  // The reference's second pass: the means over both passes, equal again.
  apply_tile_updates(reference, all_tiles(two, 7, 1, 8));
  e = compute_error_image(image, reference, 1.0f);
  EXPECT_EQ(e.passes, 2);
  EXPECT_DOUBLE_EQ(e.max_pct, 0.0);
  // Three passes against two compare the first two; a different third pass of the reference
  // shows as an error once both have three.
  apply_tile_updates(image, all_tiles(test_framebuffer(16, 8, 0.9f, 3), 9, 2, 8));
  e = compute_error_image(image, reference, 1.0f);
  EXPECT_EQ(e.passes, 2);
  EXPECT_DOUBLE_EQ(e.max_pct, 0.0);
  apply_tile_updates(reference, all_tiles(test_framebuffer(16, 8, 0.3f, 3), 7, 2, 8));
  e = compute_error_image(image, reference, 1.0f);
  EXPECT_EQ(e.passes, 3);
  EXPECT_GT(e.average_pct, 0.0);
  // A different pass 0 has an error, and the error view colours every compared pixel.
  DisplayImage other;
  apply_tile_updates(other, all_tiles(test_framebuffer(16, 8, 0.4f, 1), 11, 0, 8));
  e = compute_error_image(other, reference, 1.0f);
  EXPECT_EQ(e.passes, 1);
  EXPECT_GT(e.average_pct, 0.0);
  renderer::HeatmapRange range;
  view_rgb8(other, e, ViewMode::error, range);
  EXPECT_GT(range.max, 0.0);
  EXPECT_TRUE(view_info(ViewMode::error).value(view_pixels(other, e), 3 * 16 + 3).has_value());
}

// The error bound travels with the tiles: the view, the hover read-out and the totals show the
// framebuffer's per-pixel bound (renderer/error_bound.h), without any reference.
TEST(DisplayImage, TheErrorBoundViewShowsEachPixelsBoundWithoutAReference) {
  renderer::Framebuffer f = test_framebuffer(16, 8, 0.5f, 2);
  for (std::size_t i = 0; i < f.samples.size(); ++i) {
    // Per sample 0.01 * (i % 4) in red: the pixel's bound is that / 3 * 100 percent.
    f.error_bound_sum[i] = glm::vec3(0.02f * static_cast<float>(i % 4), 0.0f, 0.0f);
  }
  DisplayImage image;
  apply_tile_updates(image, all_tiles(f, 3, 1, 8));
  const ViewPixels pixels = view_pixels(image, ErrorImage{});
  EXPECT_NEAR(*view_info(ViewMode::bound).value(pixels, 3), 100.0 * 0.03 / 3.0, 1e-4);
  EXPECT_FALSE(view_info(ViewMode::error).value(pixels, 3).has_value());
  renderer::HeatmapRange range;
  const std::vector<std::uint8_t> bound = view_rgb8(image, ErrorImage{}, ViewMode::bound, range);
  EXPECT_DOUBLE_EQ(range.min, 0.0);
  EXPECT_NEAR(range.max, 1.0, 1e-5);
  EXPECT_NE(bound, view_rgb8(image, ErrorImage{}, ViewMode::nodes, range));
  const TileTotals t = sum_tile_totals(image);
  EXPECT_EQ(t.pixels_sampled, 128u);
  EXPECT_NEAR(t.error_bound_pct_max, 1.0, 1e-5);
  EXPECT_NEAR(t.error_bound_pct_sum / 128.0, 0.5, 1e-5);
  EXPECT_EQ(parse_view_mode("bound"), ViewMode::bound);
}

// Preview tiles of a framebuffer sampled every `step` pixels (ceil(w/step) x ceil(h/step)).
std::vector<TileUpdate> preview_tiles(const renderer::Framebuffer& preview, int step, int width,
                                      int height, std::uint64_t generation, int tile_size) {
  std::vector<TileUpdate> updates;
  int tile = 0;
  for (int y = 0; y < height; y += tile_size) {
    for (int x = 0; x < width; x += tile_size, ++tile) {
      updates.push_back(copy_preview_tile(
          preview, step, width, height, generation, tile,
          {x, y, std::min(x + tile_size, width), std::min(y + tile_size, height)}));
    }
  }
  return updates;
}

TEST(DisplayImage, APreviewCoversTheFrameOnScreenButNeverTheSavedViews) {
  const int w = 21, h = 13;  // not multiples of the step
  DisplayImage image;
  PreviewImage preview;
  apply_tile_updates(image, all_tiles(test_framebuffer(w, h, 0.8f, 1), 3, 0, 8));
  // The next render's coarse preview starts its generation: no samples, no totals.
  const renderer::Framebuffer coarse = test_framebuffer((w + 3) / 4, (h + 3) / 4, 0.3f, 1);
  EXPECT_TRUE(apply_preview_updates(preview, image, preview_tiles(coarse, 4, w, h, 4, 8)));
  EXPECT_EQ(image.generation, 4u);
  EXPECT_EQ(sum_tile_totals(image).samples, 0u);
  for (std::uint32_t s : image.samples) ASSERT_EQ(s, 0u);
  // On screen every pixel shows its block's sample; the saved view shows none of them.
  std::vector<std::uint8_t> rgba;
  renderer::HeatmapRange range;
  compose_view_rgba(image, preview, ErrorImage{}, ViewMode::lights, rgba, range);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) {
    ASSERT_FALSE(rgba[4 * i] == kNotRenderedRgb[0] && rgba[4 * i + 1] == kNotRenderedRgb[1] &&
                 rgba[4 * i + 2] == kNotRenderedRgb[2])
        << i;
  }
  const std::vector<std::uint8_t> saved = view_rgb8(image, ErrorImage{}, ViewMode::lights, range);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(saved[c], kNotRenderedRgb[c]);
  // Pixel (7, 5) is in the block of preview pixel (1, 1).
  EXPECT_FLOAT_EQ(preview.lights_tested[5 * w + 7], static_cast<float>((1 * coarse.width + 1) % 5));
  // A finer level replaces the coarse one, and never the other way round.
  const renderer::Framebuffer fine = test_framebuffer((w + 1) / 2, (h + 1) / 2, 0.6f, 1);
  apply_preview_updates(preview, image, preview_tiles(fine, 2, w, h, 4, 8));
  apply_preview_updates(preview, image, preview_tiles(coarse, 4, w, h, 4, 8));
  EXPECT_EQ(preview.step[5 * w + 7], 2);
  EXPECT_FLOAT_EQ(preview.lights_tested[5 * w + 7], static_cast<float>((2 * fine.width + 3) % 5));
  // The render's own tiles take over where they arrive; a stale preview is ignored.
  const renderer::Framebuffer full = test_framebuffer(w, h, 0.5f, 1);
  apply_tile_updates(image, all_tiles(full, 4, 0, 8));
  EXPECT_EQ(image.rgb, renderer::framebuffer_rgb8(full));
  EXPECT_FALSE(apply_preview_updates(preview, image, preview_tiles(coarse, 4, w, h, 3, 8)));
}

// Log axes: equal ratios are equal distances, an error of 0 sits on the floor below every other
// point, and each point is labelled with its tolerance and its speedup over rt's pass 0.
// The legend's lock keeps a heatmap's range for later renders: the composition draws over it
// and returns it, until unlocked; views that are not min..max ranges have no lock.
TEST(DisplayImage, ALockedRangeIsKeptForLaterRenders) {
  DisplayImage image;
  apply_tile_updates(image, all_tiles(test_framebuffer(16, 8, 0.5f, 1), 3, 0, 8));
  ViewerState state;
  state.view = ViewMode::lights;
  state.heatmap_range = {0.0, 40.0};
  set_range_lock(state, true);
  ASSERT_TRUE(locked_range(state).has_value());
  PreviewImage preview;
  std::vector<std::uint8_t> locked_rgba, own_rgba;
  renderer::HeatmapRange range;
  compose_view_rgba(image, preview, ErrorImage{}, ViewMode::lights, locked_rgba, range, {},
                    kDefaultMaskThresholdPct, {}, locked_range(state));
  EXPECT_EQ(range.max, 40.0);
  compose_view_rgba(image, preview, ErrorImage{}, ViewMode::lights, own_rgba, range);
  EXPECT_EQ(range.max, 4.0);  // lights tested i % 5: its own maximum
  EXPECT_NE(locked_rgba, own_rgba);
  set_range_lock(state, false);
  EXPECT_FALSE(locked_range(state).has_value());
  state.view = ViewMode::difference;
  set_range_lock(state, true);
  EXPECT_FALSE(locked_range(state).has_value());
}

TEST(TradePlot, LogAxesSpreadDecadesEvenlyAndLabelsNameToleranceAndSpeedup) {
  std::vector<TradePoint> points = {{lev::Method::lev, 0.1, 0.01, 1.0, 5.0, false, 1, 1},
                                    {lev::Method::lev, 0.01, 0.1, 0.1, 1.0, false, 1, 2},
                                    {lev::Method::lev, 0.001, 1.0, 0.01, 0.1, false, 1, 3},
                                    {lev::Method::rt, 0.01, 10.0, 0.0, 0.0, false, 1, 4}};
  const TradeAxes axes = trade_axes(points);
  const double x0 = trade_x(axes, 0.01), x1 = trade_x(axes, 0.1), x2 = trade_x(axes, 1.0);
  const double x3 = trade_x(axes, 10.0);
  EXPECT_GT(x0, 0.0);
  EXPECT_LT(x3, 1.0);
  EXPECT_NEAR(x1 - x0, x2 - x1, 1e-12);
  EXPECT_NEAR(x2 - x1, x3 - x2, 1e-12);
  const double y0 = trade_y(axes, 1.0), y1 = trade_y(axes, 0.1), y2 = trade_y(axes, 0.01);
  EXPECT_NEAR(y0 - y1, y1 - y2, 1e-12);
  EXPECT_LT(y0, 1.0);
  EXPECT_EQ(trade_y(axes, 0.0), 0.0);  // the floor
  EXPECT_GT(y2, 0.0);                  // above it
  EXPECT_EQ(trade_label(points[1], 2.0), "0.01, 20x");
  EXPECT_EQ(trade_label(points[1], 0.0), "0.01");  // rt's pass 0 not known yet
  EXPECT_EQ(trade_label(points[3], 10.0), "rt, 1x");
  // One point: a range around it, inside the plot.
  const TradeAxes single = trade_axes({points[1]});
  EXPECT_GT(trade_x(single, 0.1), 0.0);
  EXPECT_LT(trade_x(single, 0.1), 1.0);
}

TEST(TradePlot, PointsBelongToOneReferenceAndReplaceTheSameSetting) {
  TradePlot plot;
  follow_reference(plot, 4);
  add_trade_point(plot, {lev::Method::lev, 0.01, 0.5, 0.2, 3.0, false, 1, 10});
  add_trade_point(plot, {lev::Method::lev, 0.1, 0.2, 1.2, 9.0, false, 1, 11});
  add_trade_point(plot, {lev::Method::lev, 0.01, 0.4, 0.2, 3.0, false, 4, 12});
  EXPECT_EQ(plot.points.size(), 2u);
  EXPECT_EQ(trade_point_passes(plot, 12), 4);
  EXPECT_EQ(trade_point_passes(plot, 10), 0);
  follow_reference(plot, 4);
  EXPECT_EQ(plot.points.size(), 2u);
  follow_reference(plot, 5);
  EXPECT_TRUE(plot.points.empty());
}

// lev_cut at two relative errors (lev_mc at two lights per point) are two points, labelled with
// the setting that tells them apart; one changed only in a setting the method ignores (lev_cut's
// tolerance) replaces the point. Keyed by method and tolerance, each replaced the one before.
TEST(TradePlot, EverySettingAMethodReadsMakesAPointOfItsOwn) {
  TradePlot plot;
  follow_reference(plot, 4);
  TradePoint cut{lev::Method::lev_cut, 0.01, 0.5, 0.2, 3.0, false, 1, 10};
  cut.relative_error = 0.02;
  add_trade_point(plot, cut);
  cut.relative_error = 0.005;
  cut.generation = 11;
  add_trade_point(plot, cut);
  ASSERT_EQ(plot.points.size(), 2u);
  EXPECT_EQ(trade_label(plot.points[0], 0.0), "0.02");
  EXPECT_EQ(trade_label(plot.points[1], 0.0), "0.005");
  cut.tolerance = 0.1;  // lev_cut does not read it
  cut.generation = 12;
  add_trade_point(plot, cut);
  EXPECT_EQ(plot.points.size(), 2u);
  EXPECT_EQ(trade_point_passes(plot, 12), 1);

  TradePoint mc{lev::Method::lev_mc, 0.01, 0.5, 0.2, 3.0, false, 1, 20};
  add_trade_point(plot, mc);
  mc.lights_per_point = 4;
  mc.generation = 21;
  add_trade_point(plot, mc);
  ASSERT_EQ(plot.points.size(), 4u);
  EXPECT_EQ(trade_label(plot.points[3], 0.0), "0.01 k=4");
  EXPECT_EQ(trade_label(plot.points[2], 0.0), "0.01");
}

TEST(FrameLog, ReportsFrameTimesAndFirstTileLatency) {
  FrameLog log;
  for (int i = 0; i < 10; ++i) record_frame(log, 16.0 + i, 5.0, i % 2 == 0);
  const auto t0 = std::chrono::steady_clock::now();
  record_post(log, "tolerance=0.1", 7, t0);
  record_first_tile(log, 6, t0 + std::chrono::milliseconds(5));
  EXPECT_LT(log.latencies[0].first_tile_ms, 0.0);
  record_first_tile(log, 8, t0 + std::chrono::milliseconds(40));
  EXPECT_NEAR(log.latencies[0].first_tile_ms, 40.0, 1e-6);
  const FrameTimeSummary s = summarize_frames(log.frame_ms);
  EXPECT_EQ(s.frames, 10u);
  EXPECT_DOUBLE_EQ(s.max_ms, 25.0);
  EXPECT_NE(frame_report(log).find("tolerance=0.1: first tile on screen after 40.0 ms"),
            std::string::npos);
}

TEST(FrameLog, ADisabledLogRecordsNothing) {
  FrameLog log;
  log.enabled = false;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 100; ++i) record_frame(log, 16.0, 5.0, true);
  record_post(log, "tolerance=0.1", 1, t0);
  record_first_tile(log, 1, t0);
  record_preview(log, 1, true, t0);
  EXPECT_TRUE(log.frame_ms.empty());
  EXPECT_TRUE(log.busy_frame_ms.empty());
  EXPECT_TRUE(log.work_ms.empty());
  EXPECT_TRUE(log.latencies.empty());
}

TEST(FrameLog, ReportsTheWholeFramePreviewAndEveryLevel) {
  FrameLog log;
  const auto t0 = std::chrono::steady_clock::now();
  record_post(log, "method=rt", 3, t0);
  record_first_tile(log, 3, t0 + std::chrono::milliseconds(20));
  record_preview(log, 2, false, t0 + std::chrono::milliseconds(30));  // an older render
  EXPECT_LT(log.latencies[0].whole_frame_ms, 0.0);
  record_preview(log, 3, false, t0 + std::chrono::milliseconds(70));
  record_preview(log, 3, false, t0 + std::chrono::milliseconds(90));  // the first one counts
  record_preview(log, 3, true, t0 + std::chrono::milliseconds(400));
  EXPECT_NE(frame_report(log).find("method=rt: first tile on screen after 20.0 ms, whole-frame "
                                   "preview after 70.0 ms, every preview level after 400.0 ms"),
            std::string::npos)
      << frame_report(log);
  // A change that started no render (the tolerance under rt) never claims a later change's tiles.
  record_post(log, "tolerance=0.1", 4, t0 + std::chrono::seconds(1));
  record_post(log, "method=lev", 5, t0 + std::chrono::seconds(2));
  record_first_tile(log, 5, t0 + std::chrono::milliseconds(2050));
  EXPECT_LT(log.latencies[1].first_tile_ms, 0.0);
  EXPECT_NEAR(log.latencies[2].first_tile_ms, 50.0, 1e-6);
  EXPECT_NE(frame_report(log).find("tolerance=0.1: no new tile"), std::string::npos);
}

}  // namespace
