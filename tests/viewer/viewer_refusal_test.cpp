// The real viewer window refusing what it must refuse and writing only where it may: no display,
// bad scripted changes, scripts and outputs that are devices or inputs, writers that write a
// device in place, a snapshot that cannot be written, a full device, a signal during the scene
// load. Each exits with its code and one line, and leaves the folder as it was.
#include <array>

#include "tests/support/viewer_window.h"

namespace {

using namespace levrt_test;  // the shared fixture and helpers (tests/support/viewer_window.h)

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
  // The message names the range the value left: the largest side, a frame count's digits.
  for (const auto& [flag, value, range] : std::vector<std::array<std::string, 3>>{
           {"--window", "99999x240", "from 320x240 to 16384x16384"},
           {"--frames", "1e3", "must be an integer in [0, 2147483647], got '1e3'"},
           {"--frames", "-1", "must be an integer in [0, 2147483647], got '-1'"},
           {"--frames", "99999999999", "must be an integer in [0, 2147483647]"}}) {
    const CommandRun refused = run_shell("env -u DISPLAY " + shell_quote(LEVRT_BINARY) + " view " +
                                         flag + " " + shell_quote(value));
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_EQ(line_count(refused.output), 1) << refused.output;
    EXPECT_NE(refused.output.find(flag + ": "), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find(range), std::string::npos) << refused.output;
  }
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

// What a script would only fail at while it runs (a light count or level the scene lacks, one
// missed-light draw, a typed size over the memory budget), would wait for forever (an inspected
// pixel outside the image) or would drop without a word (a change past the last frame) is refused
// before the window opens: one line naming the change, exit 2, nothing written. Before: the
// screenshot of frame 1 was written and the run ended with exit 2, exit 1 or exit 0 without the
// late screenshot.
// A bad line of a --script file is named by its number.
TEST_F(ViewerWindow, WhatAScriptWouldFailAtWhileRunningIsRefusedBeforeAnythingIsWritten) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  std::ofstream(path("script.txt")) << "await=idle@0\nlights=65@2\n";
  const auto before = files_in(dir_);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--set", "lights=65@3"}, "got 'lights=65@3'"},
      {{"--set", "lights= -1@3"}, "got 'lights= -1@3'"},
      {{"--set", "screenshot=" + path("late.png") + "@10"}, "past the last frame"},
      {{"--set", "missed-draws=1@2"}, "--missed-draws"},
      {{"--set", "width=16384@2", "--set", "height=16384@3"}, "got 'height=16384@3'"},
      {{"--script", path("script.txt")}, "got 'lights=65@2'"},
      {{"--set", "inspect=100,10@2"}, "inside the 32x24 image"},
      // A level the scene lacks, as a light count: it was logged as "cannot open hall" (exit 0).
      {{"--set", "scene=hall@1", "--set", "level=10@2"}, "hall has levels 3..8, got '10'"},
  };
  for (const auto& [change, message] : cases) {
    std::vector<std::string> args = {"--lights", "64",
                                     "--width",  "32",
                                     "--height", "24",
                                     "--spp",    "1",
                                     "--window", "640x480",
                                     "--frames", "5",
                                     "--set",    "screenshot=" + path("early.png") + "@1"};
    args.insert(args.end(), change.begin(), change.end());
    const CommandRun r = run_viewer(args);
    EXPECT_EQ(r.exit_code, 2) << change[1] << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_EQ(files_in(dir_), before) << change[1] << ": " << r.output;
  }
  std::ofstream(path("script.txt")) << "await=idle@0\n\nlights=x@2\n";
  const CommandRun line = run_viewer({"--frames", "5", "--script", path("script.txt")});
  EXPECT_EQ(line.exit_code, 2) << line.output;
  EXPECT_NE(line.output.find("--script: " + path("script.txt") + " line 3: "), std::string::npos)
      << line.output;
}

// A screenshot on standard output is all that stream holds: the scripted reports and the closing
// "wrote" note go to stderr, as `render --out -` sends its summary there. Before, the note was
// appended to the PNG, and a memory report written before it.
TEST_F(ViewerWindow, AScreenshotOnStandardOutputIsAloneOnIt) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const XvfbServer xvfb;
  ASSERT_FALSE(xvfb.display().empty());
  const CommandRun r =
      run_shell("{ DISPLAY=" + xvfb.display() +
                " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " + shell_quote(LEVRT_BINARY) +
                " view --lights 64 --width 32 --height 24 --spp 1 --window 640x480 --frames 3"
                " --set memory=report@1 --set trade=report@2 --screenshot - > " +
                shell_quote(path("shot.png")) + "; }");  // stderr alone to the output read
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("resident memory at frame 1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("trade plot at frame 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("wrote -"), std::string::npos) << r.output;
  const std::string png = read_file_bytes(path("shot.png"));
  EXPECT_EQ(png.rfind("\x89PNG", 0), 0u);
  const std::string iend("IEND\xae\x42\x60\x82", 8);
  ASSERT_GE(png.size(), iend.size());
  EXPECT_EQ(png.substr(png.size() - iend.size()), iend) << "trailing bytes after the PNG";
  EXPECT_TRUE(read_png(path("shot.png")).ok());
  // Standard output named by a path, a pipe: the same.
  const CommandRun named = run_shell(
      "{ { DISPLAY=" + xvfb.display() + " ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " +
      shell_quote(LEVRT_BINARY) +
      " view --lights 64 --width 32 --height 24 --spp 1 --window 640x480 --frames 3"
      " --set memory=report@1 --screenshot /dev/stdout; echo \"levrt exit $?\" >&2; } | cat > " +
      shell_quote(path("piped.png")) + "; }");
  ASSERT_NE(named.output.find("levrt exit 0"), std::string::npos) << named.output;
  EXPECT_NE(named.output.find("resident memory at frame 1"), std::string::npos) << named.output;
  const std::string piped = read_file_bytes(path("piped.png"));
  ASSERT_GE(piped.size(), iend.size());
  EXPECT_EQ(piped.substr(piped.size() - iend.size()), iend) << "trailing bytes after the PNG";
}

// A scene whose file name is not UTF-8 (Latin-1 'é'): the controls file and a snapshot's stats
// are written, the invalid byte as U+FFFD. Before: exit 1 with nlohmann's "invalid UTF-8 byte".
TEST_F(ViewerWindow, ASceneFileNameThatIsNotUtf8IsWrittenToTheControlsAndTheSnapshot) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::string scene = path("caf\xe9.gltf");
  levrt_test::write_file(scene, levrt_test::gltf_document(levrt_test::triangle_buffers() + R"(,
        "nodes": [{"mesh": 0, "children": [1]},
                  {"translation": [0.2, 0.2, 1],
                   "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5}]}})"));
  const CommandRun r =
      run_viewer({"--scene", scene, "--width", "32", "--height", "24", "--spp", "1", "--window",
                  "640x480", "--frames", "3", "--controls", path("controls.json"), "--set",
                  "snapshot=" + path("snap") + "@1"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json controls = read_json(path("controls.json"));
  ASSERT_TRUE(controls.is_object()) << read_file_bytes(path("controls.json"));
  EXPECT_EQ(controls["settings"]["scene"], path("caf\xef\xbf\xbd.gltf"));
  nlohmann::json stats;
  for (const auto& entry : fs::directory_iterator(dir_ / "snap")) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 11 && name.substr(name.size() - 11) == "_stats.json")
      stats = read_json(entry.path());
  }
  ASSERT_TRUE(stats.is_object()) << r.output;
  EXPECT_EQ(stats["scene"], "caf\xef\xbf\xbd");
}

// A path with a newline or an escape in a message of the running viewer (printed by scripted
// sessions) is escaped: each message one line, no escape sequence reaching the terminal.
TEST_F(ViewerWindow, MessagesNamingAPathWithControlCharactersStayOneLineEach) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::string scene = path("evil\x1b[31mred\nsecond.json");
  const CommandRun r = run_viewer({"--lights", "64", "--width", "32", "--height", "24", "--spp",
                                   "1", "--window", "640x480", "--frames", "4", "--set",
                                   "scene=" + scene + "@1", "--set", "await=idle@2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_EQ(line_count(r.output), 2) << r.output;  // opening ..., cannot open ...
  EXPECT_NE(r.output.find("opening " + path("evil\\x1b[31mred\\nsecond.json")), std::string::npos)
      << r.output;
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
  // A path whose last name is too long: the folders made before it go too (they stayed).
  const CommandRun long_name = run_viewer(
      {"--lights", "64", "--width", "64", "--height", "48", "--spp", "1", "--frames", "3", "--set",
       "snapshot=" + path("new") + "/sub/" + std::string(300, 'a') + "@1"});
  EXPECT_EQ(long_name.exit_code, 1) << long_name.output;
  EXPECT_EQ(line_count(long_name.output), 1) << long_name.output;
  EXPECT_EQ(files_in(dir_), before) << long_name.output;
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

// Snapshot, then view again from its camera (--camera-from its stats) and snapshot the same
// settings after a scene round trip, which drops the command line's camera: the second snapshot
// replaced the stats it had read. It is written beside them now (_2).
TEST_F(ViewerWindow, ASecondSnapshotOfTheSameSettingsReplacesNothing) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::vector<std::string> size = {"--lights", "64", "--width", "32",
                                         "--height", "24", "--spp",   "1"};
  std::vector<std::string> first = size;
  first.insert(first.end(), {"--frames", "2", "--set", "snapshot=" + path("snap") + "@0"});
  ASSERT_EQ(run_viewer(first).exit_code, 0);
  const fs::path camera = dir_ / "snap" / "view_building_64_lev_0.01_stats.json";
  const std::string bytes = read_file_bytes(camera);
  ASSERT_FALSE(bytes.empty());
  std::vector<std::string> again = size;
  again.insert(again.end(), {"--camera-from", camera.string(), "--frames", "6", "--set",
                             "scene=maze@1", "--set", "scene=building@2", "--set", "await=idle@3",
                             "--set", "snapshot=" + path("snap") + "@4"});
  const CommandRun r = run_viewer(again);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file_bytes(camera), bytes);
  const nlohmann::json second = read_json(dir_ / "snap" / "view_building_64_lev_0.01_2_stats.json");
  ASSERT_TRUE(second.is_object()) << r.output;
  EXPECT_EQ(second["lights"], 64);
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

// For a test that starts the viewer itself (to signal it): this process's DISPLAY is `xvfb`, and
// LeakSanitizer's exit-time scan is off, as run_viewer_on_xvfb sets them: its report of Mesa's
// one-off allocations is no part of how the viewer exits.
void run_here_on_xvfb(const XvfbServer& xvfb) {
  ::setenv("DISPLAY", xvfb.display().c_str(), 1);
  const char* asan = std::getenv("ASAN_OPTIONS");
  ::setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + ":detect_leaks=0").c_str(), 1);
}

// A signal after the session wrote a snapshot, a screenshot and its controls file: it said
// "interrupted; no output written" while the files stood in the folder. Exit 130 and one line
// naming each file written before the signal.
TEST_F(ViewerWindow, ASignalAfterASnapshotNamesTheFilesWrittenBeforeIt) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const XvfbServer xvfb;
  ASSERT_FALSE(xvfb.display().empty());
  run_here_on_xvfb(xvfb);
  const fs::path stats = dir_ / "snap" / "view_building_64_lev_0.01_stats.json";
  const levrt_test::InterruptedRun run = levrt_test::interrupt_and_read(
      {LEVRT_BINARY, "view",
       "--lights",   "64",
       "--width",    "32",
       "--height",   "24",
       "--spp",      "1",
       "--window",   "640x480",
       "--frames",   "100000000",
       "--controls", path("controls.json"),
       "--set",      "snapshot=" + path("snap") + "@0",
       "--set",      "screenshot=" + path("shot.png") + "@1"},
      SIGTERM, std::chrono::milliseconds(0),
      [&](pid_t) { return fs::exists(stats) && fs::exists(path("shot.png")); });
  EXPECT_EQ(run.exit_code, 130) << run.errors;
  EXPECT_EQ(line_count(run.errors), 1) << run.errors;
  EXPECT_EQ(run.errors.find("no output written"), std::string::npos) << run.errors;
  EXPECT_NE(run.errors.find("levrt: interrupted after writing "), std::string::npos) << run.errors;
  for (const std::string& file :
       {path("controls.json"), path("shot.png"), (dir_ / "snap").string() + "/view_building"}) {
    EXPECT_NE(run.errors.find(file), std::string::npos) << file << ": " << run.errors;
  }
}

// A script of two snapshots printed only the last one's "wrote" line: each is named.
TEST_F(ViewerWindow, EverySnapshotOfAScriptedSessionIsNamed) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const CommandRun r =
      run_viewer({"--lights", "64", "--width", "32", "--height", "24", "--spp", "1", "--window",
                  "640x480", "--frames", "4", "--set", "snapshot=" + path("snap") + "@0", "--set",
                  "method=rt@1", "--set", "snapshot=" + path("snap") + "@2"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string stem : {"view_building_64_lev_0.01", "view_building_64_rt"}) {
    EXPECT_TRUE(fs::exists(dir_ / "snap" / (stem + "_stats.json"))) << stem;
    EXPECT_NE(r.output.find("levrt view: wrote " + path("snap") + "/" + stem + ".png"),
              std::string::npos)
        << stem << ": " << r.output;
  }
}

// Ctrl-C while the viewer's worker loads a scene that takes seconds (tests/support/slow_gltf.h):
// the viewer exits 130 promptly (the load stops at its next step, or the load watchdog ends it),
// with no screenshot written.
TEST_F(ViewerWindow, SignalDuringTheSceneLoadExitsPromptlyWithNothingWritten) {
  if (!have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const XvfbServer xvfb;
  ASSERT_FALSE(xvfb.display().empty());
  run_here_on_xvfb(xvfb);
  const fs::path scene = levrt_test::write_slow_loading_gltf(dir_);
  fs::create_directories(dir_ / "out");
  for (int sig : {SIGINT, SIGTERM}) {
    EXPECT_EQ(levrt_test::interrupted_while(
                  {LEVRT_BINARY, "view", "--scene", scene.string(), "--window", "800x600",
                   "--frames", "5", "--screenshot", path("out/shot.png")},
                  sig, std::chrono::milliseconds(100),
                  [](pid_t pid) {
                    // Its window is open and its buffer read: the load's long steps have begun
                    // (a fixed 800 ms after the handlers came too early once at a load of 14).
                    return levrt_test::has_read_at_least(pid, levrt_test::kSlowGltfBufferBytes);
                  }),
              "loading the scene")
        << "signal " << sig;
    EXPECT_TRUE(fs::is_empty(dir_ / "out")) << "signal " << sig;
  }
}

}  // namespace
