// The real viewer window under Xvfb, in scripted mode: open, render, switch method, move the
// tolerance mid-render, switch every view (the error view computes the rt reference), save a
// snapshot, and write the window to a PNG; the coarse preview covers the frame, never reaches a
// snapshot, and the fit resolution follows the window. Skipped only when Xvfb is missing.
// Labelled "threads": under the tsan preset the UI thread, the tile workers and the reference
// thread share the display buffers and the cancel flag. Its refusals and writers:
// viewer_refusal_test.cpp.
#include "tests/support/viewer_window.h"

namespace {

using namespace levrt_test;  // the shared fixture and helpers (tests/support/viewer_window.h)

TEST_F(ViewerWindow, AFileOpenedWhileRunningLoadsAndABadOneKeepsTheSceneShown) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const auto lit_triangle = [](const std::string& light) {
    return levrt_test::gltf_document(levrt_test::triangle_buffers() + R"(,
        "nodes": [{"mesh": 0, "children": [1]},
                  {"translation": [0.2, 0.2, 1],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [)" +
                                     light + "]}}");
  };
  levrt_test::write_file(dir_ / "good.gltf", lit_triangle(R"({"type": "point", "intensity": 5})"));
  levrt_test::write_file(dir_ / "bad.gltf",
                         lit_triangle(R"({"type": "point", "intensity": 5, "range": 0})"));
  const CommandRun refused =
      levrt_test::run_levrt({"render", "--scene", path("bad.gltf"), "--width", "8", "--height", "8",
                             "--out", path("never.png")});
  ASSERT_EQ(refused.exit_code, 2) << refused.output;
  std::string message = refused.output.substr(refused.output.find(": ") + 2);
  message.erase(message.find_last_not_of('\n') + 1);

  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "64", "--width", "64", "--height", "48", "--spp", "1", "--window", "800x600",
      "--frames", "10",
      "--set", "await=idle@0",
      "--set", "drop=" + path("good.gltf") + "@1",
      "--set", "await=idle@2",
      "--set", "snapshot=" + path("good") + "@3",
      "--set", "scene=" + path("bad.gltf") + "@4",
      "--set", "await=idle@5",
      "--set", "snapshot=" + path("kept") + "@6",
      "--set", "screenshot=" + path("kept.png") + "@7"});
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("opening " + path("good.gltf")), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("cannot open " + path("bad.gltf") + ": " + message + " (kept " +
                          path("good.gltf") + ")"),
            std::string::npos)
      << "expected the whole message: " << message << "\n"
      << r.output;
  for (const std::string folder : {"good", "kept"}) {
    nlohmann::json stats;
    for (const auto& entry : fs::directory_iterator(dir_ / folder)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > 11 && name.substr(name.size() - 11) == "_stats.json")
        stats = read_json(entry.path());
    }
    ASSERT_TRUE(stats.is_object()) << folder << ": " << r.output;
    EXPECT_EQ(stats["scene"], "good") << folder;  // the file's name, as stats name a scene
    EXPECT_EQ(stats["lights"], 1) << folder;
  }
  EXPECT_TRUE(read_png(path("kept.png")).ok());
}

// The camera flags set the viewer's view, and Copy camera gives that view back as the same flags
// (scripted sessions print what is copied).
TEST_F(ViewerWindow, TheCameraFlagsSetTheViewAndCopyCameraGivesThemBack) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const CommandRun r = run_viewer({"--lights",
                                   "64",
                                   "--width",
                                   "48",
                                   "--height",
                                   "36",
                                   "--spp",
                                   "1",
                                   "--window",
                                   "800x600",
                                   "--frames",
                                   "3",
                                   "--camera-position",
                                   "2,-14,7",
                                   "--camera-target",
                                   "0.5,0,1",
                                   "--fov",
                                   "35",
                                   "--set",
                                   "await=idle@0",
                                   "--set",
                                   "copy=camera@1"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("camera: --camera-position 2,-14,7 --camera-target 0.5,0,1 "
                          "--camera-up 0,0,1 --fov 35"),
            std::string::npos)
      << r.output;
}

// Copy camera before the scene has loaded gave the renderer's default camera (0,-10,5 looking at
// the origin), not the scene's: a scripted copy now waits for the scene, and the panel's button
// says the camera is not known yet.
TEST_F(ViewerWindow, CopyCameraBeforeTheSceneHasLoadedGivesTheScenesCamera) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const CommandRun r =
      run_viewer({"--lights", "64", "--width", "48", "--height", "36", "--spp", "1", "--window",
                  "800x600", "--frames", "2", "--set", "copy=camera@0"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CommandRun rendered =
      levrt_test::run_levrt({"render", "--lights", "64", "--width", "8", "--height", "8", "--quiet",
                             "--stats", path("stats.json"), "--out", path("x.png")});
  ASSERT_EQ(rendered.exit_code, 0) << rendered.output;
  const nlohmann::json camera = read_json(path("stats.json"))["camera"];
  const std::size_t at = r.output.find("camera: --camera-position ");
  ASSERT_NE(at, std::string::npos) << r.output;
  // The copied flags render the same view as the preset.
  std::istringstream words(r.output.substr(at + 8, r.output.find('\n', at) - at - 8));
  std::vector<std::string> args = {"render",  "--lights",          "64",    "--width",
                                   "8",       "--height",          "8",     "--quiet",
                                   "--stats", path("copied.json"), "--out", path("y.png")};
  for (std::string word; words >> word;) args.push_back(word);
  ASSERT_EQ(levrt_test::run_levrt(args).exit_code, 0);
  const nlohmann::json copied = read_json(path("copied.json"))["camera"];
  for (const char* key : {"position", "target", "up"}) {
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(copied[key][i].get<double>(), camera[key][i].get<double>(), 1e-3)
          << key << ": " << r.output;
  }
}

// The panel greys out what the chosen method ignores (the settings table's unused_because), and
// the controls file says which: lev_cut has no tolerance and draws no samples but uses the
// relative error; lev the other way round.
TEST_F(ViewerWindow, ThePanelGreysOutWhatTheMethodIgnores) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  for (const std::string method : {"lev", "lev_cut"}) {
    const CommandRun r = run_viewer({"--lights", "64", "--width", "48", "--height", "36",
                                     "--window", "800x600", "--frames", "3", "--controls",
                                     path("controls.json"), "--set", "method=" + method + "@1"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json controls = read_json(path("controls.json"));
    ASSERT_TRUE(controls.is_object()) << r.output;
    const nlohmann::json& unused = controls["unused"];
    EXPECT_EQ(controls["settings"]["method"], method);
    EXPECT_EQ(unused.contains("tolerance"), method == "lev_cut") << unused.dump();
    EXPECT_EQ(unused.contains("relative-error"), method == "lev") << unused.dump();
    EXPECT_TRUE(unused.contains("lights-per-point")) << unused.dump();
    EXPECT_TRUE(unused.contains("camera")) << unused.dump();  // building is no glTF file
  }
}

TEST_F(ViewerWindow, ScriptedSessionRendersSwitchesEverythingAndScreenshots) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::string final_png = path("final.png");
  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "64", "--width", "128", "--height", "96", "--spp", "2", "--window", "1024x640",
      "--frames", "40", "--screenshot", final_png, "--report-fps",
      "--set", "await=idle@0",
      "--set", "screenshot=" + path("before.png") + "@1",
      "--set", "method=ast@2",               // switch the method
      "--set", "tolerance=0.3@3",            // and move the tolerance while it renders
      "--set", "method=lev@5",
      "--set", "tolerance=1@6",
      "--set", "await=idle@7",
      "--set", "screenshot=" + path("tolerance.png") + "@8",
      "--set", "view=lights@9",
      "--set", "await=idle@10",
      "--set", "screenshot=" + path("lights.png") + "@11",
      "--set", "view=nodes@12",
      "--set", "view=error@14",              // starts the rt reference
      "--set", "await=idle@15",
      "--set", "hover=64,48@16",
      "--set", "screenshot=" + path("error.png") + "@17",
      "--set", "snapshot=" + path("snap") + "@18",
      "--set", "view=image@20",
      "--set", "lights=256@22",              // a new scene level, rebuilt on the worker
      "--set", "await=idle@23",
  });
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("frames while tracing"), std::string::npos) << r.output;

  const Png final_shot = read_png(final_png);
  ASSERT_TRUE(final_shot.ok()) << r.output;
  EXPECT_EQ(final_shot.width, 1024);
  EXPECT_EQ(final_shot.height, 640);
  EXPECT_FALSE(uniform(final_shot));

  const Png before = read_png(path("before.png"));
  const Png tolerance = read_png(path("tolerance.png"));
  const Png lights = read_png(path("lights.png"));
  const Png error = read_png(path("error.png"));
  ASSERT_TRUE(before.ok() && tolerance.ok() && lights.ok() && error.ok()) << r.output;
  for (const Png* p : {&before, &tolerance, &lights, &error}) {
    EXPECT_EQ(p->width, 1024);
    EXPECT_EQ(p->height, 640);
    EXPECT_FALSE(uniform(*p));
  }
  // Each change shows in the picture itself, not only in the panel.
  EXPECT_GT(picture_differences(before, tolerance), 1000);
  EXPECT_GT(picture_differences(tolerance, lights), 1000);
  EXPECT_GT(picture_differences(lights, error), 1000);

  for (const char* f : {"view_building_64_lev_1.png", "view_building_64_lev_1_error.png",
                        "view_building_64_lev_1_stats.json"}) {
    EXPECT_TRUE(fs::exists(dir_ / "snap" / f)) << f << "\n" << r.output;
  }
}

TEST_F(ViewerWindow, TheNoiseViewOfASamplingMethodShowsAndSnapshotsItsEstimate) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // clang-format off
  const CommandRun r = run_viewer({
      "--scene", "hall", "--lights", "64", "--method", "lev_mc", "--tolerance", "0.3",
      "--lights-per-point", "2",
      "--width", "96", "--height", "72", "--spp", "6", "--window", "1024x640", "--frames", "8",
      "--set", "await=idle@0",
      "--set", "screenshot=" + path("image.png") + "@1",
      "--set", "view=noise@2",
      "--set", "await=idle@3",
      "--set", "screenshot=" + path("noise.png") + "@4",
      "--set", "snapshot=" + path("snap") + "@5",
  });
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Png image = read_png(path("image.png"));
  const Png noise = read_png(path("noise.png"));
  ASSERT_TRUE(image.ok() && noise.ok()) << r.output;
  EXPECT_FALSE(uniform(noise));
  EXPECT_GT(picture_differences(image, noise), 1000);
  const fs::path stats = dir_ / "snap" / "view_hall_64_lev_mc_0.3_k2_stats.json";
  ASSERT_TRUE(fs::exists(dir_ / "snap" / "view_hall_64_lev_mc_0.3_k2_noise.png")) << r.output;
  ASSERT_TRUE(fs::exists(stats)) << r.output;
  const std::string json = read_file_bytes(stats);
  EXPECT_NE(json.find("\"std_error_avg_pct\""), std::string::npos) << json;
}

TEST_F(ViewerWindow, OnceThePreviewIsDoneNoPixelIsGreyAfterAChangeToRt) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::string shot = path("preview.png");
  // The lights view shows unrendered pixels in the grey; rt at 4,096 lights takes seconds for
  // its first pass, so right after the preview most tiles are still being traced.
  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "4096", "--method", "lev", "--width", "128", "--height", "96", "--spp", "1",
      "--window", "1024x640", "--frames", "4",
      "--set", "view=lights@0",
      "--set", "await=idle@0",
      "--set", "method=rt@1",
      "--set", "await=preview@2",
      "--set", "screenshot=" + shot + "@3",
  });
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Png png = read_png(shot);
  ASSERT_TRUE(png.ok()) << r.output;
  EXPECT_EQ(not_rendered_pixels(png), 0);
  EXPECT_FALSE(uniform(png));
}

// The viewer's snapshot of `settings` at its first idle frame and `levrt render` of the same
// settings, both in `dir`, the snapshot named `snapshot_name` (without its ending): both PNGs'
// bytes and both stats (empty or discarded when a run failed, with its output in `failures`).
struct SnapshotBesideRender {
  std::string snapshot_png, render_png;
  nlohmann::json snapshot_stats, render_stats;
  std::string failures;
};

SnapshotBesideRender snapshot_beside_render(const fs::path& dir,
                                            const std::vector<std::string>& settings,
                                            const std::string& snapshot_name) {
  SnapshotBesideRender out;
  std::vector<std::string> view_args = settings;
  for (const char* a : {"--window", "1024x640", "--frames", "3", "--set", "await=idle@0", "--set"})
    view_args.emplace_back(a);
  view_args.push_back("snapshot=" + (dir / "snap").string() + "@1");
  const CommandRun view = run_viewer(view_args);
  if (view.exit_code != 0) out.failures += view.output;

  std::string render = shell_quote(LEVRT_BINARY) + " render --quiet";
  for (const std::string& a : settings) render += " " + shell_quote(a);
  render += " --out " + shell_quote((dir / "headless.png").string()) + " --stats " +
            shell_quote((dir / "headless_stats.json").string());
  const CommandRun headless = run_shell(render);
  if (headless.exit_code != 0) out.failures += headless.output;

  out.snapshot_png = read_file_bytes(dir / "snap" / (snapshot_name + ".png"));
  out.render_png = read_file_bytes(dir / "headless.png");
  out.snapshot_stats = read_json(dir / "snap" / (snapshot_name + "_stats.json"));
  out.render_stats = read_json(dir / "headless_stats.json");
  return out;
}

TEST_F(ViewerWindow, PreviewSamplesNeverReachASnapshot) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // ast carries per-light statistics from pass to pass: a preview that fed them would change
  // pass 1. Two passes, a typed size, the same settings as the headless render; ast's own
  // selection, not rt's loop (renderer/rt_fallback.h).
  const SnapshotBesideRender r =
      snapshot_beside_render(dir_,
                             {"--lights", "256", "--method", "ast", "--width", "96", "--height",
                              "64", "--spp", "2", "--rt-fallback", "off"},
                             "view_building_256_ast_0.01");
  ASSERT_TRUE(r.failures.empty()) << r.failures;
  EXPECT_FALSE(r.snapshot_png.empty());
  EXPECT_TRUE(r.snapshot_png == r.render_png);
  const nlohmann::json& a = r.snapshot_stats;
  const nlohmann::json& b = r.render_stats;
  ASSERT_FALSE(a.is_discarded() || b.is_discarded());
  for (const char* key :
       {"lights", "method", "tolerance", "relative_error", "lights_per_point", "width", "height",
        "spp", "shading_points", "shadow_rays", "lights_tested_avg", "lights_tested_max",
        "nodes_visited_avg", "hierarchy_bytes"}) {
    ASSERT_TRUE(a.contains(key) && b.contains(key)) << key;
    EXPECT_EQ(a[key], b[key]) << key;
  }
}

// The viewer makes the rt fallback's choice as `levrt render` does (renderer/rt_fallback.h): lev
// at tolerance 0 casts every ray rt casts and walks besides, so both shade with rt's loop, walk
// no hierarchy, and say so in their stats; the image is the same.
TEST_F(ViewerWindow, TheRtFallbackIsChosenAsTheHeadlessRenderChoosesIt) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const SnapshotBesideRender r = snapshot_beside_render(
      dir_, {"--lights", "64", "--tolerance", "0", "--width", "64", "--height", "48", "--spp", "1"},
      "view_building_64_lev_0");
  ASSERT_TRUE(r.failures.empty()) << r.failures;
  EXPECT_FALSE(r.snapshot_png.empty());
  EXPECT_TRUE(r.snapshot_png == r.render_png);
  const nlohmann::json& a = r.snapshot_stats;
  const nlohmann::json& b = r.render_stats;
  ASSERT_FALSE(a.is_discarded() || b.is_discarded());
  ASSERT_TRUE(a["rt_fallback"].is_object()) << a.dump();
  EXPECT_TRUE(a["rt_fallback"]["used"].get<bool>());
  EXPECT_EQ(a["rt_fallback"], b["rt_fallback"]);
  EXPECT_EQ(a["nodes_visited_avg"].get<double>(), 0.0);
  EXPECT_EQ(a["shadow_rays"], b["shadow_rays"]);
}

// The "Error bound" view needs no reference: it shows the certified bound per pixel, its hover
// read-out and stats say the same as `levrt render` of the same settings, and no rt is rendered.
TEST_F(ViewerWindow, TheErrorBoundViewShowsTheBoundWithoutTheReference) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // lev's own selection, whose bound is not zero (rt's loop, renderer/rt_fallback.h, has none).
  const std::vector<std::string> settings = {"--scene", "hall", "--lights",      "256",
                                             "--width", "128",  "--height",      "96",
                                             "--spp",   "1",    "--rt-fallback", "off"};
  std::vector<std::string> view_args = settings;
  // clang-format off
  for (const std::string& a : std::vector<std::string>{
           "--window", "1024x640", "--frames", "8",
           "--set", "await=idle@0",
           "--set", "screenshot=" + path("image.png") + "@1",
           "--set", "view=bound@2",
           "--set", "await=idle@3",
           "--set", "hover=64,40@4",
           "--set", "screenshot=" + path("bound.png") + "@5",
           "--set", "snapshot=" + path("snap") + "@6"})
    view_args.push_back(a);
  // clang-format on
  const CommandRun view = run_viewer(view_args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  const Png image = read_png(path("image.png"));
  const Png bound = read_png(path("bound.png"));
  ASSERT_TRUE(image.ok() && bound.ok()) << view.output;
  EXPECT_GT(picture_differences(image, bound), 1000);

  std::string render = shell_quote(LEVRT_BINARY) + " render --quiet";
  for (const std::string& a : settings) render += " " + shell_quote(a);
  render += " --stats " + shell_quote(path("render_stats.json"));
  const CommandRun headless = run_shell(render);
  ASSERT_EQ(headless.exit_code, 0) << headless.output;
  const fs::path snap = dir_ / "snap";
  EXPECT_TRUE(fs::exists(snap / "view_hall_256_lev_0.01_bound.png")) << view.output;
  const nlohmann::json a = read_json(snap / "view_hall_256_lev_0.01_stats.json");
  const nlohmann::json b = read_json(path("render_stats.json"));
  ASSERT_FALSE(a.is_discarded() || b.is_discarded()) << view.output;
  EXPECT_FALSE(a.contains("pixel_error_avg_pct"));  // the view started no reference
  EXPECT_GT(a["error_bound_max_pct"].get<double>(), 0.0);
  // The viewer keeps each pixel's bound as a float: the same numbers to float precision.
  for (const char* key : {"error_bound_avg_pct", "error_bound_max_pct"}) {
    EXPECT_NEAR(a[key].get<double>(), b[key].get<double>(), 1e-5 * b[key].get<double>()) << key;
  }
}

TEST_F(ViewerWindow, RenderStatsAndSnapshotStatsHaveTheSameKeys) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // One function writes both files (app/render_stats.h): the keys cannot drift, and threads 0
  // is resolved to the core count in both.
  const std::vector<std::string> settings = {"--lights", "64", "--width",   "48",
                                             "--height", "32", "--threads", "0"};
  std::vector<std::string> view_args = settings;
  // The viewer renders two passes, not its 64 (await=idle waits for them all), the headless
  // render its one: the spread between passes is a number in one file and null in the other.
  for (const char* a :
       {"--spp", "2", "--window", "800x600", "--frames", "3", "--set", "await=idle@0", "--set"})
    view_args.emplace_back(a);
  view_args.push_back("snapshot=" + path("keys") + "@1");
  const CommandRun view = run_viewer(view_args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  std::string render = shell_quote(LEVRT_BINARY) + " render --quiet";
  for (const std::string& a : settings) render += " " + shell_quote(a);
  render += " --stats " + shell_quote(path("render_stats.json"));
  const CommandRun headless = run_shell(render);
  ASSERT_EQ(headless.exit_code, 0) << headless.output;

  nlohmann::json snapshot;
  for (const auto& entry : fs::directory_iterator(dir_ / "keys")) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 11 && name.compare(name.size() - 11, 11, "_stats.json") == 0)
      snapshot = read_json(entry.path());
  }
  const nlohmann::json rendered = read_json(path("render_stats.json"));
  ASSERT_TRUE(snapshot.is_object() && rendered.is_object()) << view.output;
  std::vector<std::string> snapshot_keys, render_keys;
  for (const auto& item : snapshot.items()) snapshot_keys.push_back(item.key());
  for (const auto& item : rendered.items()) render_keys.push_back(item.key());
  EXPECT_EQ(snapshot_keys, render_keys);
  EXPECT_GT(snapshot["threads"].get<int>(), 0);
  EXPECT_EQ(snapshot["threads"], rendered["threads"]);
  EXPECT_EQ(snapshot["depth"], rendered["depth"]);
}

TEST_F(ViewerWindow, TheFitResolutionFollowsTheImageArea) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::string controls = path("controls.json");
  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "64", "--spp", "1", "--window", "640x480", "--frames", "9",
      "--controls", controls,
      "--set", "await=idle@0",
      "--set", "snapshot=" + path("small") + "@1",
      "--set", "window=760x540@2",           // as a user dragging the border
      "--set", "await=idle@3",
      "--set", "snapshot=" + path("large") + "@4",
      "--set", "resolution=fit/2@5",
      "--set", "await=idle@6",
      "--set", "snapshot=" + path("half") + "@7",
  });
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto stats = [&](const char* folder) {
    for (const auto& entry : fs::directory_iterator(dir_ / folder)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > 11 && name.compare(name.size() - 11, 11, "_stats.json") == 0)
        return read_json(entry.path());
    }
    return nlohmann::json();
  };
  const nlohmann::json small = stats("small"), large = stats("large"), half = stats("half");
  ASSERT_TRUE(small.is_object() && large.is_object() && half.is_object()) << r.output;
  const nlohmann::json c = read_json(controls);
  ASSERT_TRUE(c.is_object() && c["controls"].contains("image_area")) << r.output;
  // The last controls file is of the resized window: the render is the image area's size.
  const nlohmann::json area = c["controls"]["image_area"];
  const int area_width = static_cast<int>(area[2].get<double>() - area[0].get<double>());
  const int area_height = static_cast<int>(area[3].get<double>() - area[1].get<double>());
  EXPECT_EQ(large["width"].get<int>(), area_width);
  EXPECT_EQ(large["height"].get<int>(), area_height);
  EXPECT_LT(small["width"].get<int>(), large["width"].get<int>());
  EXPECT_LT(small["height"].get<int>(), large["height"].get<int>());
  EXPECT_EQ(half["width"].get<int>(), area_width / 2);
  EXPECT_EQ(half["height"].get<int>(), area_height / 2);
  EXPECT_EQ(c["settings"]["resolution"], "fit/2");
}

// A layout change never restarts a render: at a fit resolution the render's size follows the
// window alone. lev -> ast adds what the statistics show (ast's method memory), which used to
// grow the statistics pane by a row, shrink the picture and so restart the render, the rt
// reference and the trade plot. Small and cheap: 16 lights, one pass.
TEST_F(ViewerWindow, AMethodChangeKeepsTheFitSizeTheReferenceAndTheTradePlot) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "16", "--spp", "1", "--method", "lev", "--window", "900x640",
      "--frames", "8",
      "--set", "reference=on@0",
      "--set", "await=idle@1",
      "--set", "snapshot=" + path("lev") + "@2",
      "--set", "trade=report@3",
      "--set", "method=ast@4",
      "--set", "await=idle@5",
      "--set", "snapshot=" + path("ast") + "@6",
      "--set", "trade=report@7",
  });
  // clang-format on
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto stats = [&](const char* folder) {
    for (const auto& entry : fs::directory_iterator(dir_ / folder)) {
      const std::string name = entry.path().filename().string();
      if (name.find("_stats.json") != std::string::npos) return read_json(entry.path());
    }
    return nlohmann::json();
  };
  const nlohmann::json lev = stats("lev"), ast = stats("ast");
  ASSERT_TRUE(lev.is_object() && ast.is_object()) << r.output;
  EXPECT_EQ(lev["method"], "lev");
  EXPECT_EQ(ast["method"], "ast");
  EXPECT_EQ(ast["width"], lev["width"]) << r.output;
  EXPECT_EQ(ast["height"], lev["height"]) << r.output;
  // The same reference, never restarted, and the plot holds both methods.
  const std::vector<levrt_test::TradeReport> reports = levrt_test::trade_reports(r.output);
  ASSERT_EQ(reports.size(), 2u) << r.output;
  EXPECT_NE(reports[0].reference, 0u) << r.output;
  EXPECT_EQ(reports[1].reference, reports[0].reference) << r.output;
  EXPECT_EQ(reports[0].points, 1) << r.output;
  EXPECT_EQ(reports[1].points, 2) << r.output;
}

}  // namespace
