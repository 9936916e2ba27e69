// The real viewer window under Xvfb, in scripted mode: open, render, switch method, move the
// tolerance mid-render, switch every view (the error view computes the rt reference), save a
// snapshot, and write the window to a PNG; the coarse preview covers the frame, never reaches a
// snapshot, and the fit resolution follows the window. Skipped only when Xvfb is missing.
// Labelled "threads": under the tsan preset the UI thread, the tile workers and the reference
// thread share the display buffers and the cancel flag.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/gltf_files.h"
#include "tests/support/png_file.h"
#include "tests/support/run_command.h"
#include "tests/support/signal_process.h"
#include "tests/support/slow_gltf.h"
#include "tests/support/trade_report.h"
#include "tests/support/xvfb_server.h"

namespace {

using levrt_test::CommandRun;
using levrt_test::have_xvfb;
using levrt_test::run_shell;
using levrt_test::shell_quote;
using levrt_test::XvfbServer;
namespace fs = std::filesystem;

CommandRun run_viewer(const std::vector<std::string>& args) {
  return levrt_test::run_viewer_on_xvfb(args);
}

using Png = levrt_test::PngImage;

Png read_png(const fs::path& path) {
  return levrt_test::read_png_image(path);
}

bool uniform(const Png& png) {
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        if (png.at(x, y)[c] != png.at(0, 0)[c]) return false;
      }
    }
  }
  return true;
}

// Pixels that differ inside the picture (right of the panel, above the statistics).
int picture_differences(const Png& a, const Png& b) {
  int differences = 0;
  for (int y = a.height * 15 / 100; y < a.height * 55 / 100; ++y) {
    for (int x = a.width / 2; x < a.width * 9 / 10; ++x) {
      if (a.at(x, y)[0] != b.at(x, y)[0] || a.at(x, y)[1] != b.at(x, y)[1] ||
          a.at(x, y)[2] != b.at(x, y)[2]) {
        ++differences;
      }
    }
  }
  return differences;
}

std::string read_file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(read_file_bytes(path), nullptr, false);
}

// The viewer's "not rendered yet" grey (app/viewer/display_image.h, kNotRenderedRgb).
int not_rendered_pixels(const Png& png) {
  int count = 0;
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      const unsigned char* p = png.at(x, y);
      if (p[0] == 38 && p[1] == 38 && p[2] == 42) ++count;
    }
  }
  return count;
}

class ViewerWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    // The pid keeps concurrent runs (other build folders, ctest -j) apart.
    dir_ = fs::temp_directory_path() /
           ("levrt_view_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ViewerWindow, WithoutADisplayExitsTwoNamingTheHeadlessRoute) {
  const CommandRun r =
      run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + shell_quote(LEVRT_BINARY) + " view");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("levrt render"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("display"), std::string::npos) << r.output;
}

TEST_F(ViewerWindow, BadScriptedChangesExitTwoBeforeOpeningAWindow) {
  for (const char* change :
       {"tolerance=abc@3", "view=sideways@1", "colour=red@2", "method=lev", "ab=x@0", "swipe=2@0",
        "swipe=nan@0", "mask_threshold=-1@0", "mask_threshold=nan@0", "range_lock=maybe@0"}) {
    const CommandRun r = run_shell("env -u DISPLAY " + shell_quote(LEVRT_BINARY) +
                                   " view --frames 3 --set " + shell_quote(change));
    EXPECT_EQ(r.exit_code, 2) << change << ": " << r.output;
    EXPECT_NE(r.output.find("--set"), std::string::npos) << r.output;
  }
  const CommandRun r =
      run_shell("env -u DISPLAY " + shell_quote(LEVRT_BINARY) + " view --window 10x10");
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

long line_count(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

// Every file in the folder with its bytes (or its kind), to show that nothing changed.
std::map<std::string, std::string> files_in(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    files[fs::relative(e.path(), dir).string()] =
        e.is_regular_file() ? read_file_bytes(e.path()) : "(not a regular file)";
  }
  return files;
}

// The device node stays the same device: never replaced by a regular file.
void expect_same_device(const char* device, const struct stat& before) {
  struct stat after {};
  ASSERT_EQ(::stat(device, &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << device;
  EXPECT_EQ(after.st_rdev, before.st_rdev) << device;
  EXPECT_EQ(after.st_ino, before.st_ino) << device;
}

TEST_F(ViewerWindow, AScriptThatIsNotASmallRegularFileIsRefusedBeforeItIsRead) {
  const CommandRun device = run_shell("env -u DISPLAY " + shell_quote(LEVRT_BINARY) +
                                      " view --frames 1 --script /dev/zero");
  EXPECT_EQ(device.exit_code, 2) << device.output;
  EXPECT_EQ(line_count(device.output), 1) << device.output;
  EXPECT_NE(device.output.find("--script: is not a regular file"), std::string::npos)
      << device.output;
  const std::string big = path("big.txt");
  fs::resize_file((std::ofstream(big), big), (std::uintmax_t{16} << 20) + 1);
  const CommandRun large = run_shell("env -u DISPLAY " + shell_quote(LEVRT_BINARY) +
                                     " view --frames 1 --script " + shell_quote(big));
  EXPECT_EQ(large.exit_code, 2) << large.output;
  EXPECT_EQ(line_count(large.output), 1) << large.output;
  EXPECT_NE(large.output.find("more than the 16 MiB a script may have"), std::string::npos)
      << large.output;
}

TEST_F(ViewerWindow, AnOutputThatIsAnInputOrAnotherOutputIsRefusedBeforeTheWindowOpens) {
  std::ofstream(path("script.txt")) << "await=idle@0\n";
  std::ofstream(path("scene.json")) << "{}";
  const auto before = files_in(dir_);
  const std::vector<std::vector<std::string>> cases = {
      {"--script", path("script.txt"), "--controls", path("script.txt")},
      {"--scene", path("scene.json"), "--controls", path("scene.json")},
      {"--screenshot", path("a.png"), "--set", "screenshot=" + dir_.string() + "/./a.png@1"},
      {"--controls", path("c.json"), "--screenshot", path("c.json")},
  };
  for (const auto& args : cases) {
    std::vector<std::string> all = {"--frames", "2"};
    all.insert(all.end(), args.begin(), args.end());
    std::string command = "env -u DISPLAY " + shell_quote(LEVRT_BINARY) + " view";
    for (const std::string& a : all) command += " " + shell_quote(a);
    const CommandRun r = run_shell(command);
    EXPECT_EQ(r.exit_code, 2) << args[1] << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_EQ(files_in(dir_), before) << args[1];
  }
}

TEST_F(ViewerWindow, EveryWriterWritesADeviceInPlace) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  struct stat null_before {
  }, zero_before{};
  ASSERT_EQ(::stat("/dev/null", &null_before), 0);
  ASSERT_EQ(::stat("/dev/zero", &zero_before), 0);
  // The snapshot's image file is a pipe that a reader drains: written in place, still a pipe.
  fs::create_directories(dir_ / "snap");
  const fs::path pipe = dir_ / "snap" / "view_building_64_lev_0.01.png";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const fs::path received = dir_ / "received.png";
  std::thread reader([&] {
    run_shell("timeout 120 cat " + shell_quote(pipe.string()) + " > " +
              shell_quote(received.string()));
  });
  // clang-format off
  const CommandRun r = run_viewer({
      "--lights", "64", "--width", "64", "--height", "48", "--spp", "1", "--window", "800x600",
      "--frames", "3", "--screenshot", "/dev/zero", "--controls", "/dev/null",
      "--set", "snapshot=" + path("snap") + "@1",
  });
  // clang-format on
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  expect_same_device("/dev/null", null_before);
  expect_same_device("/dev/zero", zero_before);
  EXPECT_TRUE(fs::is_fifo(pipe));
  EXPECT_TRUE(read_png(received).ok()) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "snap" / "view_building_64_lev_0.01_stats.json")) << r.output;
}

TEST_F(ViewerWindow, BadInputExitsTwoWithOneLineAndWritesNothing) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::ofstream(path("broken.json")) << R"({"levrt_scene": 1, "camera": 5})";
  const std::vector<std::vector<std::string>> cases = {
      {"--scene", path("missing.json")},
      {"--scene", path("broken.json")},
      {"--scene", "building", "--level", "99"},
      {"--width", "16384", "--height", "16384"},
  };
  const auto before = files_in(dir_);
  for (const auto& scene : cases) {
    std::vector<std::string> args = scene;
    for (const std::string& a : std::vector<std::string>{
             "--frames", "3", "--window", "800x600", "--screenshot", path("shot.png"), "--controls",
             path("controls.json"), "--set", "snapshot=" + path("snap") + "@1", "--set",
             "screenshot=" + path("early.png") + "@0"}) {
      args.push_back(a);
    }
    const CommandRun r = run_viewer(args);
    EXPECT_EQ(r.exit_code, 2) << scene[1] << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_EQ(files_in(dir_), before) << scene[1] << ": " << r.output;
  }
}

// A scene file opened while the viewer runs (a simulated drop, then the scene control as typed
// into the path field): the good one loads and renders; the bad one keeps the good scene on
// screen, the session goes on (exit 0), and its message is logged whole: the same line
// `levrt render` prints for it.
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
    EXPECT_TRUE(unused.contains("samples")) << unused.dump();
    EXPECT_TRUE(unused.contains("camera")) << unused.dump();  // building is no glTF file
  }
}

TEST_F(ViewerWindow, ASnapshotThatCannotBeWrittenExitsOne) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::ofstream(path("file.txt")) << "a file, not a folder";
  const auto before = files_in(dir_);
  // One pass: the snapshot waits for the whole render, whose size does not matter here.
  const CommandRun r =
      run_viewer({"--lights", "64", "--width", "64", "--height", "48", "--spp", "1", "--frames",
                  "3", "--set", "snapshot=" + path("file.txt") + "/snap@1"});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("snapshot failed"), std::string::npos) << r.output;
  EXPECT_EQ(files_in(dir_), before);
}

// Without await=idle the snapshot waits for the render: all passes of it, not the preview.
TEST_F(ViewerWindow, ASnapshotRequestedBeforeTheRenderIsCompleteWaitsForIt) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const CommandRun r =
      run_viewer({"--lights", "256", "--width", "96", "--height", "64", "--spp", "3", "--window",
                  "800x600", "--frames", "1", "--set", "snapshot=" + path("snap") + "@0"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json stats = read_json(dir_ / "snap" / "view_building_256_lev_0.01_stats.json");
  ASSERT_TRUE(stats.is_object()) << r.output;
  EXPECT_EQ(stats["spp"], 3);
}

// As root a rename would replace the machine's /dev/full; written in place it reports ENOSPC
// and the viewer exits 1.
TEST_F(ViewerWindow, AFullDeviceAsTheControlsFileIsWrittenInPlaceAndExitsOne) {
  if (::geteuid() != 0 || !fs::is_character_file("/dev/full"))
    GTEST_SKIP() << "needs root and /dev/full: the test writes the device itself";
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const XvfbServer xvfb;
  ASSERT_FALSE(xvfb.display().empty());
  struct stat full_before {};
  ASSERT_EQ(::stat("/dev/full", &full_before), 0);
  const CommandRun full =
      run_shell("DISPLAY=" + xvfb.display() +
                " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " + shell_quote(LEVRT_BINARY) +
                " view --lights 64 --width 64 --height 48 --frames 3 --controls /dev/full");
  EXPECT_EQ(full.exit_code, 1) << full.output;
  EXPECT_NE(full.output.find("No space left on device"), std::string::npos) << full.output;
  expect_same_device("/dev/full", full_before);
}

// Ctrl-C while the viewer's worker loads a scene that takes seconds (tests/support/slow_gltf.h):
// the viewer exits 130 promptly (the load stops at its next step, or the load watchdog ends it),
// with no screenshot written.
TEST_F(ViewerWindow, SignalDuringTheSceneLoadExitsPromptlyWithNothingWritten) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const XvfbServer xvfb;
  ASSERT_FALSE(xvfb.display().empty());
  ::setenv("DISPLAY", xvfb.display().c_str(), 1);
  // As run_viewer_on_xvfb does: LeakSanitizer's exit-time scan (and its report of Mesa's one-off
  // allocations) is no part of how promptly the viewer exits.
  const char* asan = std::getenv("ASAN_OPTIONS");
  ::setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + ":detect_leaks=0").c_str(), 1);
  const fs::path scene = levrt_test::write_slow_loading_gltf(dir_);
  fs::create_directories(dir_ / "out");
  for (int sig : {SIGINT, SIGTERM}) {
    EXPECT_EQ(levrt_test::interrupt_after(
                  {LEVRT_BINARY, "view", "--scene", scene.string(), "--window", "800x600",
                   "--frames", "5", "--screenshot", path("out/shot.png")},
                  sig, std::chrono::milliseconds(800), std::chrono::seconds(2)),
              130)
        << "signal " << sig;
    EXPECT_TRUE(fs::is_empty(dir_ / "out")) << "signal " << sig;
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
      "--samples", "2",
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
  const fs::path stats = dir_ / "snap" / "view_hall_64_lev_mc_0.3_stats.json";
  ASSERT_TRUE(fs::exists(dir_ / "snap" / "view_hall_64_lev_mc_0.3_noise.png")) << r.output;
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

TEST_F(ViewerWindow, PreviewSamplesNeverReachASnapshot) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // ast carries per-light statistics from pass to pass: a preview that fed them would change
  // pass 1. Two passes, a typed size, the same settings as the headless render below.
  const std::vector<std::string> settings = {"--lights", "256",      "--method", "ast",   "--width",
                                             "96",       "--height", "64",       "--spp", "2"};
  std::vector<std::string> view_args = settings;
  for (const char* a : {"--window", "1024x640", "--frames", "3", "--set", "await=idle@0", "--set"})
    view_args.emplace_back(a);
  view_args.push_back("snapshot=" + path("snap") + "@1");
  const CommandRun view = run_viewer(view_args);
  ASSERT_EQ(view.exit_code, 0) << view.output;

  std::string render = shell_quote(LEVRT_BINARY) + " render --quiet";
  for (const std::string& a : settings) render += " " + shell_quote(a);
  render += " --out " + shell_quote(path("headless.png")) + " --stats " +
            shell_quote(path("headless_stats.json"));
  const CommandRun headless = run_shell(render);
  ASSERT_EQ(headless.exit_code, 0) << headless.output;

  const fs::path snap = dir_ / "snap" / "view_building_256_ast_0.01.png";
  ASSERT_TRUE(fs::exists(snap)) << view.output;
  const std::string snapshot_png = read_file_bytes(snap);
  EXPECT_FALSE(snapshot_png.empty());
  EXPECT_TRUE(snapshot_png == read_file_bytes(path("headless.png")));

  const nlohmann::json a = read_json(dir_ / "snap" / "view_building_256_ast_0.01_stats.json");
  const nlohmann::json b = read_json(path("headless_stats.json"));
  ASSERT_FALSE(a.is_discarded() || b.is_discarded());
  for (const char* key :
       {"lights", "method", "tolerance", "relative_error", "light_samples", "width", "height",
        "spp", "shading_points", "shadow_rays", "lights_tested_avg", "lights_tested_max",
        "nodes_visited_avg", "hierarchy_bytes"}) {
    ASSERT_TRUE(a.contains(key) && b.contains(key)) << key;
    EXPECT_EQ(a[key], b[key]) << key;
  }
}

// The "Error bound" view needs no reference: it shows the certified bound per pixel, its hover
// read-out and stats say the same as `levrt render` of the same settings, and no rt is rendered.
TEST_F(ViewerWindow, TheErrorBoundViewShowsTheBoundWithoutTheReference) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::vector<std::string> settings = {"--scene", "hall",     "--lights", "256",   "--width",
                                             "128",     "--height", "96",       "--spp", "1"};
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
