// Opening scene files in the viewer without a window: a path that names no scene file is logged
// and requests nothing, a failed load puts the settings and the user's camera back to the scene
// still loaded, loaded files make the recent list (newest first, no repeats, capped), the log
// keeps the newest messages, and the scripted `drop` key opens a file as a real drop does.
#include "app/viewer/scene_opening.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "app/viewer/scripted_changes.h"

namespace {
using namespace app::viewer;

renderer::Camera orbited_camera() {
  renderer::Camera c;
  c.position = {1.0f, 2.0f, 3.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  return c;
}

// The status of a worker that has loaded `scene` (serial `loads`).
void loaded(ViewerState& state, const std::string& scene, std::uint64_t loads) {
  state.status.scene = scene;
  state.status.level = state.settings.scene.level;
  state.status.scene_serial = loads;
  follow_scene_loads(state);
}

// The status of a worker whose load of `scene` (its first failure) failed with `error`.
void failed_to_load(ViewerState& state, const std::string& scene, const std::string& error) {
  state.status.load_error = scene + ": " + error;
  state.status.load_error_scene = scene;
  state.status.load_error_serial = 1;
  follow_scene_loads(state);
}

TEST(SceneOpening, APathThatIsNoSceneFileIsLoggedAndRequestsNothing) {
  ViewerState state;
  state.request_dirty = false;
  EXPECT_FALSE(open_scene_file(state, "notes.txt"));
  EXPECT_EQ(state.settings.scene.name, "building");
  EXPECT_FALSE(state.request_dirty);
  ASSERT_EQ(state.messages.size(), 1u);
  EXPECT_TRUE(state.messages[0].problem);
  EXPECT_NE(state.messages[0].text.find("notes.txt"), std::string::npos);
  EXPECT_FALSE(open_scene_file(state, ""));
  EXPECT_EQ(state.messages.size(), 1u);
}

TEST(SceneOpening, AFailedLoadGoesBackToTheLoadedSceneAndCamera) {
  ViewerState state;
  loaded(state, "building", 1);
  state.camera = orbited_camera();
  ASSERT_TRUE(open_scene_file(state, "/scenes/broken.gltf"));
  EXPECT_EQ(state.settings.scene.name, "/scenes/broken.gltf");
  EXPECT_FALSE(state.camera.has_value());  // a new scene starts at its preset view
  EXPECT_TRUE(state.request_dirty);

  state.request_dirty = false;
  failed_to_load(state, "/scenes/broken.gltf", "lights[3].range: 0 (must be above 0)");
  EXPECT_EQ(state.settings.scene.name, "building");
  ASSERT_TRUE(state.camera.has_value());
  EXPECT_EQ(state.camera->position, orbited_camera().position);
  EXPECT_TRUE(state.request_dirty);
  ASSERT_FALSE(state.messages.empty());
  const LogMessage& last = state.messages.back();
  EXPECT_TRUE(last.problem);
  EXPECT_NE(last.text.find("lights[3].range: 0 (must be above 0)"), std::string::npos) << last.text;
  EXPECT_NE(last.text.find("kept building"), std::string::npos) << last.text;
  EXPECT_TRUE(state.recent_scenes.empty());

  // The same error is followed once.
  const std::size_t messages = state.messages.size();
  follow_scene_loads(state);
  EXPECT_EQ(state.messages.size(), messages);
}

TEST(SceneOpening, LoadedFilesMakeTheRecentListNewestFirst) {
  ViewerState state;
  std::uint64_t loads = 0;
  loaded(state, "building", ++loads);
  EXPECT_TRUE(state.recent_scenes.empty());  // a built-in model is not a file
  for (int i = 0; i < 10; ++i) loaded(state, "s" + std::to_string(i) + ".gltf", ++loads);
  ASSERT_EQ(state.recent_scenes.size(), kMaxRecentScenes);
  EXPECT_EQ(state.recent_scenes.front(), "s9.gltf");
  loaded(state, "s5.gltf", ++loads);
  EXPECT_EQ(state.recent_scenes.front(), "s5.gltf");
  EXPECT_EQ(std::count(state.recent_scenes.begin(), state.recent_scenes.end(), "s5.gltf"), 1);
  EXPECT_EQ(state.recent_scenes.size(), kMaxRecentScenes);
}

TEST(SceneOpening, TheLogKeepsTheNewestMessages) {
  ViewerState state;
  for (std::size_t i = 0; i < kMaxLogMessages + 5; ++i)
    log_message(state, "message " + std::to_string(i), false);
  ASSERT_EQ(state.messages.size(), kMaxLogMessages);
  EXPECT_EQ(state.messages.front().text, "message 5");
  EXPECT_EQ(state.messages.back().text, "message " + std::to_string(kMaxLogMessages + 4));
}

TEST(SceneOpening, ADropOpensTheFirstSceneFileAndIgnoresTheRest) {
  ViewerState state;
  EXPECT_TRUE(open_dropped_files(state, {"photo.png", "a.glb", "b.gltf"}));
  EXPECT_EQ(state.settings.scene.name, "a.glb");
  ASSERT_EQ(state.messages.size(), 3u);
  EXPECT_TRUE(state.messages[0].problem);   // photo.png: not a scene file
  EXPECT_FALSE(state.messages[1].problem);  // opening a.glb
  EXPECT_NE(state.messages[2].text.find("b.gltf: ignored"), std::string::npos);

  ViewerState scripted;
  const ScriptedChange drop = parse_scripted_change("drop=room.json@3");
  EXPECT_EQ(apply_scripted_change(scripted, drop), ScriptAction::none);
  EXPECT_EQ(scripted.settings.scene.name, "room.json");
  EXPECT_THROW(parse_scripted_change("drop=@3"), app::UsageError);
}

// A glTF opened in the running viewer is shown as `levrt render --scene FILE.gltf` shows it: auto
// exposure and the neutral curve, unless the user chose them; a built-in scene after it goes
// back to EV 0 and linear; a failed open gives the display back. It opened at linear EV 0.
TEST(SceneOpening, AnOpenedSceneGetsItsDisplayDefaultsButTheUsersChoice) {
  ViewerState state;
  loaded(state, "building", 1);
  ASSERT_TRUE(open_scene_file(state, "/scenes/lamp.gltf"));
  EXPECT_TRUE(state.settings.display.exposure_auto);
  EXPECT_EQ(state.settings.display.curve, renderer::DisplayCurve::neutral);
  loaded(state, "/scenes/lamp.gltf", 2);
  state.settings.display.exposure_ev = -4.0;  // auto's choice, as the frame loop copies it

  app::Settings before = state.settings;
  state.settings.scene.name = "maze";
  settings_changed(state, before, "scene=maze");
  EXPECT_FALSE(state.settings.display.exposure_auto);
  EXPECT_EQ(state.settings.display.exposure_ev, 0.0);
  EXPECT_EQ(state.settings.display.curve, renderer::DisplayCurve::linear);
  loaded(state, "maze", 3);

  // A curve chosen in the panel stays; the exposure still follows the scene.
  before = state.settings;
  state.settings.display.curve = renderer::DisplayCurve::srgb;
  settings_changed(state, before, "display=srgb");
  ASSERT_TRUE(open_scene_file(state, "/scenes/broken.gltf"));
  EXPECT_TRUE(state.settings.display.exposure_auto);
  EXPECT_EQ(state.settings.display.curve, renderer::DisplayCurve::srgb);
  failed_to_load(state, "/scenes/broken.gltf", "cannot read the scene file (no such file)");
  EXPECT_EQ(state.settings.scene.name, "maze");
  EXPECT_FALSE(state.settings.display.exposure_auto);
  EXPECT_EQ(state.settings.display.curve, renderer::DisplayCurve::srgb);

  // A file opened before the first scene is shown (a script's first frames), then failing.
  ViewerState early;
  ASSERT_TRUE(open_scene_file(early, "/scenes/broken.glb"));
  EXPECT_TRUE(early.settings.display.exposure_auto);
  early.status.scene = "building";
  early.status.scene_serial = 1;
  failed_to_load(early, "/scenes/broken.glb", "cannot read the scene file (no such file)");
  EXPECT_EQ(early.settings.scene.name, "building");
  EXPECT_FALSE(early.settings.display.exposure_auto);
  EXPECT_EQ(early.settings.display.curve, renderer::DisplayCurve::linear);

  // An exposure given on the command line (or typed) is kept for every scene.
  ViewerState given;
  given.exposure_chosen = true;
  given.settings.display.exposure_ev = 2.0;
  loaded(given, "building", 1);
  ASSERT_TRUE(open_scene_file(given, "/scenes/lamp.glb"));
  EXPECT_FALSE(given.settings.display.exposure_auto);
  EXPECT_EQ(given.settings.display.exposure_ev, 2.0);
  EXPECT_EQ(given.settings.display.curve, renderer::DisplayCurve::neutral);
}

// The camera index picked on one glTF (its fourth camera) is not carried to the next file, which
// may have fewer: the open failed with "camera: 3 (the file has 0 cameras in its scene)". A
// failed open gives the index back.
TEST(SceneOpening, AnotherFileOpensAtItsFirstCamera) {
  ViewerState state;
  state.settings.scene.name = "/scenes/four_cameras.gltf";
  loaded(state, "/scenes/four_cameras.gltf", 1);
  app::Settings before = state.settings;
  state.settings.scene.camera = 3;
  settings_changed(state, before, "camera=3");
  state.status.camera_index = 3;
  loaded(state, "/scenes/four_cameras.gltf", 2);
  ASSERT_TRUE(open_scene_file(state, "/scenes/no_camera.glb"));
  EXPECT_EQ(state.settings.scene.camera, 0);
  failed_to_load(state, "/scenes/no_camera.glb", "cannot read the scene file (no such file)");
  EXPECT_EQ(state.settings.scene.camera, 3);
}

}  // namespace
