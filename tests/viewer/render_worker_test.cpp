// The viewer's background worker without a window: tiles reach the UI side complete and equal to
// a direct render, new requests cancel old ones, the rt reference survives refits and scene
// changes drop it, and shutting down mid-render is prompt. Labelled "threads" (runs under tsan).
#include "app/viewer/render_worker.h"

#include <array>
#include <chrono>
#include <fstream>
#include <functional>
#include <memory>
#include <set>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "app/scene_loading.h"
#include "app/viewer/display_image.h"
#include "app/viewer/live_stats.h"
#include "app/viewer/snapshot_panel.h"
#include "lev/methods.h"
#include "renderer/display_transform.h"
#include "renderer/pixel_error.h"
#include "renderer/render.h"
#include "scenes/scene_file.h"
#include "tests/support/setting_values.h"
#include "tests/support/temp_dir.h"

namespace {
using namespace app::viewer;
using Clock = std::chrono::steady_clock;

struct Ui {
  RenderWorker worker;
  WorkerStatus status;
  DisplayImage image;
  PreviewImage preview;
  std::set<int> preview_steps;  // of every preview tile taken
  DisplayImage reference;

  // One UI frame: status first, then the tiles (as the viewer does).
  void frame() {
    status = worker.status();
    const TakenTiles main = worker.take_tiles();
    apply_tile_updates(image, main.updates);
    const TakenTiles previews = worker.take_preview_tiles();
    for (const TileUpdate& u : previews.updates) preview_steps.insert(u.preview_step);
    apply_preview_updates(preview, image, previews.updates);
    const TakenTiles ref = worker.take_reference_tiles();
    if (reference.generation != 0 && reference.generation < ref.floor)
      clear_display_image(reference);
    apply_tile_updates(reference, ref.updates);
  }

  bool run_until(const std::function<bool()>& done, double seconds = 600.0) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < deadline) {
      frame();
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

  bool settled(std::uint64_t serial) {
    return status.request_serial >= serial && status.phase == WorkerPhase::idle &&
           image.generation == status.generation;
  }
};

app::Settings small_settings() {
  app::Settings s;
  s.scene.level = 2;
  s.image.width = 48;
  s.image.height = 36;
  s.image.spp = 2;
  s.image.depth = 2;
  return s;
}

RenderRequest request_for(const app::Settings& s, bool reference = false) {
  RenderRequest r;
  r.settings = s;
  r.want_reference = reference;
  return r;
}

std::vector<std::uint8_t> direct_render_rgb8(const app::Settings& s) {
  std::unique_ptr<app::LoadedScene> loaded = app::load_scene(s.scene);
  renderer::RenderStatePtr state =
      renderer::make_render_state(loaded->scene, *loaded->rays, app::render_settings_from(s));
  for (int pass = 0; pass < s.image.spp; ++pass) renderer::render_pass(*state);
  return renderer::framebuffer_rgb8(renderer::render_framebuffer(*state));
}

TEST(RenderWorker, TheUiImageEqualsADirectRenderOfTheSameSettings) {
  Ui ui;
  const app::Settings s = small_settings();
  const std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.generation, serial);
  EXPECT_EQ(ui.status.passes_done, 2);
  EXPECT_EQ(ui.status.light_count, 16u);
  EXPECT_GT(ui.status.hierarchy_bytes, 0u);
  EXPECT_EQ(ui.image.tiles_seen, ui.status.tile_count);
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
  EXPECT_GT(sum_tile_totals(ui.image).shading_points, 0u);
  EXPECT_TRUE(ui.worker.tiles_in_flight().empty());
}

TEST(RenderWorker, EveryNewRenderStartsWithPreviewLevelsOverTheWholeFrame) {
  Ui ui;
  app::Settings s = small_settings();
  std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.preview_levels, 3);
  EXPECT_EQ(ui.status.preview_levels_done, 3);
  EXPECT_EQ(ui.preview_steps, (std::set<int>{8, 4, 2}));
  EXPECT_EQ(ui.preview.generation, serial);
  for (std::uint8_t step : ui.preview.step) ASSERT_EQ(step, 2);  // the finest level everywhere
  // The render itself is untouched by them.
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
  // A subsample stride of 4 keeps only the coarser step.
  ui.preview_steps.clear();
  s.image.subsample = 4;
  serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.preview_levels, 1);
  EXPECT_EQ(ui.preview_steps, (std::set<int>{8}));
}

TEST(RenderWorker, ALaterRequestCancelsTheRenderInFlightAndWins) {
  Ui ui;
  app::Settings slow = small_settings();
  slow.scene.level = 4;
  slow.image.width = 160;
  slow.image.height = 120;
  slow.image.spp = 1000;
  ui.worker.post(request_for(slow));
  ASSERT_TRUE(ui.run_until([&] { return ui.image.tiles_seen > 0; }));
  app::Settings fast = small_settings();
  fast.method.tolerance = 0.1;
  const std::uint64_t serial = ui.worker.post(request_for(fast));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.image.width, 48);
  EXPECT_EQ(ui.status.tolerance, 0.1);
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(fast));
}

// The mean radiance per pixel of a direct render (what the worker's tiles carry).
std::vector<glm::vec3> direct_render_radiance(const app::Settings& s) {
  std::unique_ptr<app::LoadedScene> loaded = app::load_scene(s.scene);
  renderer::RenderStatePtr state =
      renderer::make_render_state(loaded->scene, *loaded->rays, app::render_settings_from(s));
  for (int pass = 0; pass < s.image.spp; ++pass) renderer::render_pass(*state);
  const renderer::Framebuffer& f = renderer::render_framebuffer(*state);
  std::vector<glm::vec3> mean(f.radiance_sum.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < mean.size(); ++i) {
    if (f.samples[i] > 0) mean[i] = f.radiance_sum[i] / static_cast<float>(f.samples[i]);
  }
  return mean;
}

// Renders every method, changes one setting, and expects a new render exactly for the methods
// `restarts` names; either way the image is that of the new settings.
void expect_change_restarts_only(const std::function<void(app::Settings&)>& change,
                                 const std::function<bool(const lev::MethodInfo&)>& restarts) {
  for (const lev::MethodInfo& method : lev::method_table()) {
    Ui ui;
    app::Settings s = small_settings();
    s.method.method = method.id;
    const std::uint64_t first = ui.worker.post(request_for(s));
    ASSERT_TRUE(ui.run_until([&] { return ui.settled(first); })) << method.name;
    change(s);
    const std::uint64_t second = ui.worker.post(request_for(s));
    ASSERT_TRUE(ui.run_until([&] { return ui.settled(second); })) << method.name;
    EXPECT_EQ(ui.status.generation, restarts(method) ? second : first) << method.name;
    // The radiance: a render that goes on keeps the 8-bit colours of its own exposure.
    EXPECT_EQ(ui.image.radiance, direct_render_radiance(s)) << method.name;
    EXPECT_EQ(ui.image.noise_pct.size(), ui.image.samples.size());
  }
}

TEST(RenderWorker, AToleranceChangeRestartsOnlyTheMethodsThatUseIt) {
  expect_change_restarts_only([](app::Settings& s) { s.method.tolerance = 0.2; },
                              [](const lev::MethodInfo& m) { return m.uses_tolerance; });
  EXPECT_FALSE(lev::method_info(lev::Method::rt).uses_tolerance);
  EXPECT_TRUE(lev::method_info(lev::Method::lev).uses_tolerance);
}

TEST(RenderWorker, ALightsPerPointChangeRestartsOnlyTheSamplingMethods) {
  expect_change_restarts_only([](app::Settings& s) { s.method.lights_per_point = 3; },
                              [](const lev::MethodInfo& m) { return m.stochastic; });
  EXPECT_TRUE(lev::method_info(lev::Method::lev_mc).stochastic);
  EXPECT_TRUE(lev::method_info(lev::Method::light_tree).stochastic);
}

// The tolerance is in displayed units: a new exposure renders again every method that reads the
// display scale, and its image is then a fresh render's at the new exposure; rt's and the
// samplers' radiance does not depend on it, so they go on.
TEST(RenderWorker, AnExposureChangeRestartsOnlyTheMethodsThatReadTheDisplayScale) {
  expect_change_restarts_only([](app::Settings& s) { s.display.exposure_ev = 3.0; },
                              [](const lev::MethodInfo& m) { return m.reads_display_scale; });
  EXPECT_TRUE(lev::method_info(lev::Method::lev).reads_display_scale);
  EXPECT_FALSE(lev::method_info(lev::Method::rt).reads_display_scale);
}

// With the reference on, lev at a new exposure is rendered again while the rt reference goes on,
// and the error against it is `levrt render`'s at the new exposure: both exposed at it.
TEST(RenderWorker, AnExposureChangeKeepsTheReferenceAndComparesAtTheNewExposure) {
  Ui ui;
  app::Settings s = small_settings();
  s.method.tolerance = 0.1;
  const std::uint64_t first = ui.worker.post(request_for(s, true));
  ASSERT_TRUE(ui.run_until([&] {
    return ui.settled(first) && ui.status.reference == ReferencePhase::done &&
           ui.reference.tiles_seen == ui.status.reference_tile_count;
  }));
  const std::uint64_t reference_generation = ui.status.reference_generation;
  s.display.exposure_ev = 2.0;
  const std::uint64_t second = ui.worker.post(request_for(s, true));
  ASSERT_TRUE(ui.run_until(
      [&] { return ui.settled(second) && ui.status.reference == ReferencePhase::done; }));
  EXPECT_EQ(ui.status.generation, second);
  EXPECT_EQ(ui.status.reference_generation, reference_generation);
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
  app::Settings rt = s;
  rt.method.method = lev::Method::rt;
  const ErrorImage e = compute_error_image(ui.image, ui.reference, renderer::exposure_scale(2.0));
  const renderer::PixelErrorStats direct = renderer::summarize_pixel_error(
      renderer::pixel_error_pct(direct_render_rgb8(s), direct_render_rgb8(rt)));
  EXPECT_EQ(e.pixels_compared, static_cast<std::size_t>(48 * 36));
  EXPECT_GT(direct.average_pct, 0.0);
  EXPECT_DOUBLE_EQ(e.average_pct, direct.average_pct);
  EXPECT_DOUBLE_EQ(e.max_pct, direct.max_pct);
}

// The auto exposure is the EV chosen when the scene loaded: turning auto off at that EV, or on
// again whatever exposure_ev says, renders nothing again.
TEST(RenderWorker, TogglingAutoExposureAtTheEvItChoseRestartsNothing) {
  Ui ui;
  app::Settings s = small_settings();
  s.display.exposure_auto = true;
  s.display.exposure_ev = 5.0;  // what the slider said before auto: not the chosen EV
  const std::uint64_t first = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(first); }));
  ASSERT_NE(ui.status.auto_exposure_ev, 5.0);
  app::Settings chosen = s;
  chosen.display.exposure_ev = ui.status.auto_exposure_ev;
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(chosen));
  s.display.exposure_auto = false;
  s.display.exposure_ev = ui.status.auto_exposure_ev;
  std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.generation, first);
  s.display.exposure_auto = true;
  s.display.exposure_ev = -4.0;
  serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.generation, first);
}

TEST(RenderWorker, ResumedPassesKeepTheImageExact) {
  // Requests that change nothing the render depends on interrupt the pass, which then resumes.
  Ui ui;
  app::Settings s = small_settings();
  s.image.width = 96;
  s.image.height = 72;
  s.image.spp = 3;
  std::uint64_t serial = ui.worker.post(request_for(s));
  for (int i = 0; i < 20; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    serial = ui.worker.post(request_for(s));
  }
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
}

// Passes lowered below those done: the image is the render of the passes asked for. It kept
// the passes it had (4 shown, the panel saying 2), unlike `levrt render --spp 2`.
TEST(RenderWorker, FewerPassesThanDoneShowTheImageOfThePassesAskedFor) {
  Ui ui;
  app::Settings s = small_settings();
  s.method.method = lev::Method::lev_mc;
  s.image.spp = 4;
  std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  ASSERT_EQ(ui.status.passes_done, 4);
  s.image.spp = 2;
  serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.passes_done, 2);
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
  // More passes again go on from there, as before.
  const std::uint64_t generation = ui.status.generation;
  s.image.spp = 3;
  serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.generation, generation);
  EXPECT_EQ(ui.image.rgb, direct_render_rgb8(s));
}

TEST(RenderWorker, TheReferenceSurvivesRefitsAndMatchesRt) {
  Ui ui;
  app::Settings s = small_settings();
  s.image.spp = 1;
  ui.worker.post(request_for(s, true));
  // Tolerance changes while the reference renders: the worker joins it, refits, resumes it.
  for (double tolerance : {0.05, 0.2, 0.0}) {
    s.method.tolerance = tolerance;
    ui.worker.post(request_for(s, true));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  s.method.method = lev::Method::rt;
  const std::uint64_t serial = ui.worker.post(request_for(s, true));
  ASSERT_TRUE(ui.run_until([&] {
    return ui.settled(serial) && ui.status.reference == ReferencePhase::done &&
           ui.reference.tiles_seen == ui.status.reference_tile_count;
  }));
  const ErrorImage e = compute_error_image(ui.image, ui.reference, 1.0f);
  EXPECT_EQ(e.pixels_compared, static_cast<std::size_t>(48 * 36));
  EXPECT_DOUBLE_EQ(e.max_pct, 0.0);
  app::Settings rt = s;
  EXPECT_EQ(ui.reference.rgb, direct_render_rgb8(rt));

  // lev at a large tolerance differs from the reference, which is still the same.
  s.method.method = lev::Method::lev;
  s.method.tolerance = 0.5;
  const std::uint64_t lev = ui.worker.post(request_for(s, true));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(lev); }));
  EXPECT_EQ(ui.status.reference, ReferencePhase::done);
  EXPECT_GT(compute_error_image(ui.image, ui.reference, 1.0f).average_pct, 0.0);
}

// Every setting of the table, changed alone while the rt reference is on, restarts in the worker
// what app::restart_needed says and nothing more: the scene (a new load), the view (the reference
// too), the method's render (the reference goes on), or nothing but the pass count. A setting
// the scene does not read (a built-in scene's camera index) keeps the render and the reference.
// A setting added to a group and to the table is checked here with no other edit.
TEST(RenderWorker, EverySettingRestartsWhatItsGroupSays) {
  int kept = 0;
  for (const app::SettingSpec& spec : app::setting_table()) {
    Ui ui;
    const app::Settings s = small_settings();
    const std::uint64_t first = ui.worker.post(request_for(s, true));
    ASSERT_TRUE(ui.run_until([&] {
      return ui.settled(first) && ui.status.reference == ReferencePhase::done;
    })) << spec.name;
    const WorkerStatus before = ui.status;
    const std::string value = levrt_test::other_setting_value(s, spec);
    ASSERT_FALSE(value.empty()) << spec.name;
    app::Settings changed = s;
    app::set_setting(changed, spec, value);
    const app::Restart restart = app::restart_needed(s, changed);
    const std::uint64_t second = ui.worker.post(request_for(changed, true));
    ASSERT_TRUE(ui.run_until([&] { return ui.settled(second); })) << spec.name;
    const std::string what = std::string(spec.name) + "=" + value;
    EXPECT_EQ(ui.status.scene_serial != before.scene_serial, restart == app::Restart::scene)
        << what;
    EXPECT_EQ(ui.status.reference_generation != before.reference_generation,
              restart >= app::Restart::view)
        << what;
    // Fewer passes than the render has done start it again (the image of the passes asked for).
    const bool fewer_passes = changed.image.spp < before.passes_done;
    EXPECT_EQ(ui.status.generation != before.generation,
              restart >= app::Restart::render || fewer_passes)
        << what;
    EXPECT_EQ(ui.status.passes_target, changed.image.spp) << what;
    if (restart == app::Restart::nothing) ++kept;
  }
  EXPECT_GT(kept, 0);  // the camera index on this built-in scene, the display settings
}

TEST(RenderWorker, ANewViewDropsTheReference) {
  Ui ui;
  app::Settings s = small_settings();
  s.image.spp = 1;
  std::uint64_t serial = ui.worker.post(request_for(s, true));
  ASSERT_TRUE(ui.run_until(
      [&] { return ui.status.reference == ReferencePhase::done && ui.settled(serial); }));
  RenderRequest moved = request_for(s, true);
  renderer::Camera camera = ui.status.preset_camera;
  camera.position.z += 3.0f;
  moved.camera = camera;
  serial = ui.worker.post(moved);
  ASSERT_TRUE(ui.run_until(
      [&] { return ui.settled(serial) && ui.status.reference == ReferencePhase::done; }));
  EXPECT_EQ(ui.status.reference_generation, serial);
  ASSERT_TRUE(ui.run_until([&] { return ui.reference.generation == serial; }));
  // Dropping the request for a reference drops it.
  serial = ui.worker.post(request_for(s, false));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_EQ(ui.status.reference, ReferencePhase::none);
  ui.frame();
  EXPECT_EQ(ui.reference.generation, 0u);
}

TEST(RenderWorker, AFailedRequestIsReportedAndTheNextOneRecovers) {
  Ui ui;
  app::Settings bad = small_settings();
  bad.scene.level = 99;
  ui.worker.post(request_for(bad));
  ASSERT_TRUE(ui.run_until([&] { return ui.status.phase == WorkerPhase::failed; }));
  EXPECT_NE(ui.status.error.find("level"), std::string::npos) << ui.status.error;
  const std::uint64_t serial = ui.worker.post(request_for(small_settings()));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  EXPECT_TRUE(ui.status.error.empty());
}

// A size whose image fits the memory budget but whose rt reference does not: the image renders,
// the reference is refused with the reason (it failed the whole render, until the reference was
// turned off). The budget is the request's, made small here: 48x36 needs 255,744 bytes alone and
// 400,896 with the reference.
TEST(RenderWorker, AReferenceOverTheMemoryBudgetIsRefusedAndTheImageStillRenders) {
  Ui ui;
  RenderRequest request = request_for(small_settings(), true);
  request.memory_budget_bytes = 300000;
  const std::uint64_t serial = ui.worker.post(request);
  ASSERT_TRUE(
      ui.run_until([&] { return ui.settled(serial) || ui.status.phase == WorkerPhase::failed; }));
  ASSERT_NE(ui.status.phase, WorkerPhase::failed) << ui.status.error;
  EXPECT_EQ(ui.status.reference, ReferencePhase::failed);
  EXPECT_NE(ui.status.error.find("rt reference not rendered: --width/--height: 48x36 with "
                                 "--reference needs about"),
            std::string::npos)
      << ui.status.error;
  EXPECT_EQ(ui.status.passes_done, 2);
  // Over the budget without the reference too: the request fails, naming the size.
  request.memory_budget_bytes = 200000;
  ui.worker.post(request);
  ASSERT_TRUE(ui.run_until([&] { return ui.status.phase == WorkerPhase::failed; }));
  EXPECT_TRUE(ui.status.bad_input);
  EXPECT_NE(ui.status.error.find("48x36 needs about"), std::string::npos) << ui.status.error;
}

// A scene file that cannot be read, asked for while another scene is shown, leaves the shown
// scene and its finished render as they were; the failure is a load error, not a failed render.
TEST(RenderWorker, ASceneThatCannotBeLoadedKeepsTheSceneOnScreen) {
  Ui ui;
  const app::Settings good = small_settings();
  // An orbited view with its rt reference: both survive the failed open.
  RenderRequest orbited = request_for(good, true);
  renderer::Camera camera;
  camera.position = {3.0f, -12.0f, 8.0f};
  camera.target = {0.5f, 0.5f, 0.0f};
  orbited.camera = camera;
  const std::uint64_t first = ui.worker.post(orbited);
  ASSERT_TRUE(ui.run_until(
      [&] { return ui.settled(first) && ui.status.reference == ReferencePhase::done; }));
  const std::vector<std::uint8_t> before = ui.image.rgb;
  const std::uint64_t loads = ui.status.scene_serial;
  const std::uint64_t reference_generation = ui.status.reference_generation;

  // As the UI asks for a new scene: its preset view (no camera), the reference still wanted.
  RenderRequest missing = request_for(good, true);
  missing.settings.scene.name = "/nonexistent-levrt-folder/missing.gltf";
  const std::uint64_t serial = ui.worker.post(missing);
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial) && ui.status.load_error_serial > 0; }));
  EXPECT_EQ(ui.status.load_error_serial, 1u);
  EXPECT_EQ(ui.status.load_error_scene, missing.settings.scene.name);
  EXPECT_NE(ui.status.load_error.find("missing.gltf"), std::string::npos) << ui.status.load_error;
  EXPECT_EQ(ui.status.scene, good.scene.name);
  EXPECT_EQ(ui.status.scene_serial, loads);
  EXPECT_TRUE(ui.status.loading_scene.empty());
  EXPECT_EQ(ui.status.generation, first);  // the render was not restarted
  EXPECT_EQ(ui.status.reference, ReferencePhase::done);
  EXPECT_EQ(ui.status.reference_generation, reference_generation);
  EXPECT_EQ(ui.image.rgb, before);

  // The next request (the UI has gone back to the old scene) renders as usual.
  RenderRequest more = orbited;
  more.settings.image.spp = 3;
  const std::uint64_t next = ui.worker.post(more);
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(next); }));
  EXPECT_EQ(ui.status.passes_done, 3);
  EXPECT_EQ(ui.status.load_error_serial, 1u);
}

// A snapshot's stats name the level the scene file states, as `levrt render --stats` does (an
// export of maze level 2 says 2; a glTF 0), not the level setting, which a file does not read: it
// said 3 (the default) for every file.
TEST(RenderWorker, ASnapshotStatesTheSceneFilesOwnLevel) {
  app::Settings model = small_settings();
  model.scene.name = "maze";
  model.scene.level = 1;
  const levrt_test::TempDir dir("levrt_worker_level_");
  const std::string file = (dir.path() / "maze1.json").string();
  {
    std::ofstream out(file);
    out << scenes::scene_file_json(app::describe_scene(model.scene));
  }
  Ui ui;
  app::Settings s = small_settings();
  s.scene.name = file;
  s.scene.level = 3;
  const std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] { return ui.settled(serial); }));
  ASSERT_EQ(ui.status.scene, file) << ui.status.error;
  const app::RenderStats stats = snapshot_stats(LiveStats{}, ui.status, s, renderer::Camera{});
  EXPECT_EQ(stats.level, 1);
}

// Save snapshot pressed mid-pass is taken when the pass in flight completes: the image it saves
// is then a render of whole passes (`levrt render --spp N`'s, N its stats' spp). It was taken at
// once: some tiles held a sample more than the rest (hall 4,096 at 320x240: stats saying 5
// passes, 417,101 shading points where a 5-pass render has 384,589).
TEST(RenderWorker, ASnapshotAskedForMidPassHoldsWholePasses) {
  Ui ui;
  app::Settings s = small_settings();
  s.scene.level = 5;
  s.image.width = 160;
  s.image.height = 120;
  s.image.spp = 3;
  const levrt_test::TempDir dir("levrt_worker_snapshot_");
  ViewerState state;
  state.settings = s;
  state.snapshot_folder = dir.path().string();
  SnapshotWriter writer;
  std::vector<std::uint8_t> saved;
  int saved_passes = 0;
  bool asked_mid_pass = false;
  const std::uint64_t serial = ui.worker.post(request_for(s));
  ASSERT_TRUE(ui.run_until([&] {
    state.status = ui.status;
    state.image = ui.image;
    const bool mid_pass = ui.status.generation == serial && ui.image.generation == serial &&
                          ui.image.tiles_done_in_pass > 0 &&
                          ui.image.tiles_done_in_pass < ui.status.tile_count;
    if (mid_pass && !asked_mid_pass && saved.empty()) {
      asked_mid_pass = true;
      request_snapshot(state);
    }
    take_requested_snapshot(state, writer, Clock::now());
    if (asked_mid_pass && !state.snapshot_requested && saved.empty()) {
      saved = state.image.rgb;
      saved_passes = state.status.passes_done;
    }
    return !saved.empty() && ui.settled(serial);
  }));
  ASSERT_TRUE(asked_mid_pass);
  writer.wait();
  EXPECT_FALSE(writer.failed()) << writer.message();
  ASSERT_GE(saved_passes, 1);
  app::Settings at = s;
  at.image.spp = saved_passes;
  EXPECT_EQ(saved, direct_render_rgb8(at)) << "saved at " << saved_passes << " passes";
}

TEST(RenderWorker, ShutsDownPromptlyMidRender) {
  auto ui = std::make_unique<Ui>();
  app::Settings slow = small_settings();
  slow.scene.level = 5;
  slow.image.width = 320;
  slow.image.height = 240;
  slow.image.spp = 1000;
  slow.image.threads = 2;
  ui->worker.post(request_for(slow, true));
  ASSERT_TRUE(
      ui->run_until([&] { return ui->image.tiles_seen > 0 && ui->reference.tiles_seen > 0; }));
  // Far from its 1,000 passes: its second waits for the reference's second (they take turns).
  ASSERT_LE(ui->status.passes_done, 1);
  const int tiles_per_pass = ui->status.tile_count;
  ASSERT_EQ(tiles_per_pass, 20 * 15);
  const app::viewer::ShutdownReport report = ui->worker.shut_down();
  // A count, not a time: only the tiles in flight at the quit may finish, at most 2 per render
  // (2 threads each), and a few more of the reference while the worker stops the method's pass
  // and tears down. A worker that let a render finish its pass, or go on to the next, would post
  // a good part of a pass's 300 tiles or more.
  EXPECT_LE(report.tiles_finished_after_quit, 12u);
  EXPECT_EQ(ui->worker.shut_down().tiles_finished_after_quit, 0u);  // a second call does nothing
  ui.reset();
}

// The pinned pixel is inspected on a thread of its own, beside the render, which is not restarted
// (a pixel is no setting); a new pixel replaces the inspection, Clear drops it, and one pinned just
// before quitting does not hold the worker's shutdown.
TEST(RenderWorker, ThePinnedPixelIsInspectedBesideTheRenderAndANewPixelReplacesIt) {
  auto ui = std::make_unique<Ui>();
  app::Settings s = small_settings();
  s.image.spp = 1000;  // still rendering while the pixels are inspected
  RenderRequest request = request_for(s);
  request.inspect_pixel = std::array<int, 2>{10, 12};
  const std::uint64_t generation = ui->worker.post(request);
  const auto inspected = [&](int x, int y) {
    const auto& view = ui->status.inspection;
    return view && view->x == x && view->y == y && view->generation == generation &&
           !ui->status.inspection_pending;
  };
  ASSERT_TRUE(ui->run_until([&] { return inspected(10, 12); }));
  EXPECT_GT(ui->status.inspection->all_rows, 0u);
  EXPECT_FALSE(ui->status.inspection->rows.empty());
  request.inspect_pixel = std::array<int, 2>{30, 5};
  ui->worker.post(request);
  ASSERT_TRUE(ui->run_until([&] { return inspected(30, 5); }));
  EXPECT_EQ(ui->status.generation, generation);  // the render went on
  request.inspect_pixel.reset();
  const std::uint64_t cleared = ui->worker.post(request);
  ASSERT_TRUE(ui->run_until([&] { return ui->status.request_serial >= cleared; }));
  EXPECT_EQ(ui->status.inspection, nullptr);
  EXPECT_FALSE(ui->status.inspection_pending);
  // A pixel outside the image has nothing to inspect, and nothing stays pending.
  request.inspect_pixel = std::array<int, 2>{s.image.width, 0};
  const std::uint64_t outside = ui->worker.post(request);
  ASSERT_TRUE(ui->run_until([&] { return ui->status.request_serial >= outside; }));
  EXPECT_EQ(ui->status.inspection, nullptr);
  EXPECT_FALSE(ui->status.inspection_pending);
  request.inspect_pixel = std::array<int, 2>{1, 1};
  ui->worker.post(request);
  ui.reset();  // quits with the inspection pending or running
}

}  // namespace
