// levrt render's output files and messages at their extremes (issues 14 and 15): special files
// written in place, symlinks followed, standard output, every path checked before the render,
// write errors with their reason, the memory budget, and one-line messages that repeat what the
// user typed.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "app/settings.h"
#include "tests/support/folder_test.h"
#include "tests/support/gltf_files.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"

namespace {

using levrt_test::line_count;
using levrt_test::read_file;
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;
using levrt_test::run_shell;
using levrt_test::shell_quote;

const std::vector<std::string> kTiny = {"--width", "8", "--height", "8", "--quiet"};

std::vector<std::string> output_render_args(std::vector<std::string> outputs) {
  std::vector<std::string> args = {"render"};
  args.insert(args.end(), kTiny.begin(), kTiny.end());
  args.insert(args.end(), outputs.begin(), outputs.end());
  return args;
}

// A shell prefix limiting the address space to `kib` KiB. AddressSanitizer reserves terabytes of
// shadow memory up front, so under it the limit is left out and the tests assert the refusal alone.
std::string address_space_limit(long kib) {
#if defined(__SANITIZE_ADDRESS__)
  (void)kib;
  return "";
#else
  return "ulimit -v " + std::to_string(kib) + " && ";
#endif
}

bool is_png(const std::string& bytes) {
  return bytes.size() > 8 && bytes.compare(1, 3, "PNG") == 0;
}

class Outputs : public levrt_test::FolderTest {
 protected:
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  // Runs levrt in the test's folder, so relative spellings resolve there.
  CommandRun run_here(const std::vector<std::string>& args) const {
    std::string command = "cd " + shell_quote(dir_.string()) + " && " + shell_quote(LEVRT_BINARY);
    for (const std::string& a : args) command += " " + shell_quote(a);
    return run_shell(command);
  }
};

// Renders with `flag` naming a FIFO that a child process (cat) reads; returns what it received.
std::string render_into_fifo(const fs::path& fifo, const std::string& flag) {
  EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path received = fifo.string() + ".received";
  std::thread reader([&] {
    run_shell("cat " + shell_quote(fifo.string()) + " > " + shell_quote(received.string()));
  });
  const CommandRun r = run_levrt(output_render_args({flag, fifo.string()}));
  reader.join();
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_fifo(fifo));
  return read_file(received);
}

TEST_F(Outputs, AFifoReadByAnotherProcessReceivesThePngAndStaysAFifo) {
  EXPECT_TRUE(is_png(render_into_fifo(dir_ / "pipe.png", "--out")));
}

TEST_F(Outputs, AFifoReceivesTheStats) {
  EXPECT_NE(render_into_fifo(dir_ / "pipe.json", "--stats").find("\"shading_points\""),
            std::string::npos);
}

TEST_F(Outputs, ASymlinkIsFollowedAndStaysASymlink) {
  fs::create_directories(dir_ / "elsewhere");
  const fs::path target = dir_ / "elsewhere" / "real.png";
  fs::create_symlink(target, path("link.png"));
  const CommandRun r = run_levrt(output_render_args({"--out", path("link.png")}));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(path("link.png")));
  EXPECT_TRUE(is_png(read_file(target)));
  EXPECT_EQ(entries(), (std::vector<std::string>{"elsewhere", "link.png"}));
}

TEST_F(Outputs, DashWritesThePngToStandardOutput) {
  // Parenthesised: run_shell appends 2>&1, which must not send stderr into the file.
  const CommandRun r = run_shell("(" + shell_quote(LEVRT_BINARY) +
                                 " render --width 8 --height 8 --out - 2>/dev/null > " +
                                 shell_quote(path("stdout.bin")) + ")");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = read_file(path("stdout.bin"));
  EXPECT_TRUE(is_png(bytes));
  // Nothing but the PNG: it ends with its IEND chunk and CRC.
  ASSERT_GT(bytes.size(), 12u);
  EXPECT_EQ(bytes.compare(bytes.size() - 8, 4, "IEND"), 0);
}

TEST_F(Outputs, ExportToDashWritesOnlyTheSceneFileToStandardOutput) {
  const CommandRun r = run_shell("(" + shell_quote(LEVRT_BINARY) +
                                 " export --scene maze --level 1 --out - 2>/dev/null > " +
                                 shell_quote(path("maze.json")) + ")");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const CommandRun rendered = run_levrt(output_render_args({"--scene", path("maze.json")}));
  EXPECT_EQ(rendered.exit_code, 0) << rendered.output;
}

TEST_F(Outputs, TwoOutputsOnStandardOutputAreRefused) {
  const CommandRun r = run_levrt(output_render_args({"--out", "-", "--heatmap-lights", "-"}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
}

// Standard output spelled two ways is one stream: `--out /dev/stdout --stats -` ran a PNG and a
// JSON together into the pipe, and `--out - >> scene.json` appended the PNG to the scene it read.
// "-" is compared by the file or pipe standard output is: refused, one line, exit 2.
TEST_F(Outputs, StandardOutputSpelledTwoWaysOrAppendedToTheSceneIsRefused) {
  const CommandRun twice = run_here(output_render_args({"--out", "/dev/stdout", "--stats", "-"}));
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  EXPECT_EQ(line_count(twice.output), 1) << twice.output;
  EXPECT_NE(twice.output.find("--stats: standard output is written by another output too"),
            std::string::npos)
      << twice.output;
  ASSERT_EQ(
      run_here({"export", "--scene", "maze", "--level", "1", "--out", "scene.json"}).exit_code, 0);
  const std::string before = read_file(path("scene.json"));
  const CommandRun appended =
      run_shell("(cd " + shell_quote(dir_.string()) + " && " + shell_quote(LEVRT_BINARY) +
                " render --scene scene.json --width 8 --height 8 --quiet --out - >> scene.json)");
  EXPECT_EQ(appended.exit_code, 2) << appended.output;
  EXPECT_EQ(line_count(appended.output), 1) << appended.output;
  EXPECT_NE(appended.output.find("--out: standard output is a file this command reads"),
            std::string::npos)
      << appended.output;
  EXPECT_EQ(read_file(path("scene.json")), before);
}

TEST_F(Outputs, SameFileSpelledDifferentlyIsRefusedBeforeRendering) {
  fs::create_directories(dir_ / "sub");
  for (const std::string& other :
       std::vector<std::string>{"./X.png", "sub/../X.png", path("X.png")}) {
    const CommandRun r =
        run_here(output_render_args({"--out", "X.png", "--heatmap-lights", other}));
    EXPECT_EQ(r.exit_code, 2) << other << ": " << r.output;
    EXPECT_NE(r.output.find("another output also writes"), std::string::npos) << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_EQ(entries(), (std::vector<std::string>{"sub"})) << other;
  }
}

TEST_F(Outputs, AHardLinkToAnotherOutputIsTheSameFile) {
  { std::ofstream(path("a.png")) << "old"; }
  fs::create_hard_link(path("a.png"), path("b.png"));
  const CommandRun r =
      run_levrt(output_render_args({"--out", path("a.png"), "--heatmap-nodes", path("b.png")}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(read_file(path("a.png")), "old");
}

TEST_F(Outputs, ANameTooLongIsRefusedBeforeRenderingWithNothingWritten) {
  const std::string long_name = std::string(296, 'n') + ".png";
  const CommandRun r = run_levrt(
      output_render_args({"--out", path("fine.png"), "--heatmap-lights", path(long_name)}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("file name of 300 bytes"), std::string::npos) << r.output;
  EXPECT_TRUE(entries().empty());
}

TEST_F(Outputs, AWrongExtensionIsRefusedWithNothingWritten) {
  for (const auto& [flag, name] :
       std::vector<std::pair<std::string, std::string>>{{"--out", "x.txt"},
                                                        {"--heatmap-lights", "x.json"},
                                                        {"--stats", "x.png"},
                                                        {"--out", "noext"}}) {
    const CommandRun r = run_levrt(output_render_args({flag, path(name)}));
    EXPECT_EQ(r.exit_code, 2) << flag << " " << name << ": " << r.output;
    EXPECT_NE(r.output.find("must end in"), std::string::npos) << r.output;
    EXPECT_TRUE(entries().empty()) << name;
  }
}

TEST_F(Outputs, DevFullStaysADeviceAndTheErrorNamesTheReason) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  struct stat before {};
  ASSERT_EQ(::stat("/dev/full", &before), 0);
  const CommandRun r = run_levrt(output_render_args({"--out", "/dev/full"}));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  struct stat after {};
  ASSERT_EQ(::stat("/dev/full", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_rdev, before.st_rdev);
}

// A folder of the kernel's file systems that access() calls writable (root may "write" /sys/kernel
// and /proc/self) takes no new file: refused before the render (it failed after it, exit 1).
TEST_F(Outputs, AFolderOnAKernelFileSystemIsRefusedBeforeRendering) {
  int tried = 0;
  for (const std::string folder : {"/sys/kernel", "/proc/self"}) {
    if (::access(folder.c_str(), W_OK) != 0) continue;
    ++tried;
    const std::string stats = folder + "/levrt_outputs_test.json";
    const CommandRun r = run_levrt(output_render_args({"--out", path("a.png"), "--stats", stats}));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--stats: folder is on "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("a kernel file system that takes no new file"), std::string::npos)
        << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_TRUE(entries().empty()) << folder;
    EXPECT_FALSE(fs::exists(stats)) << stats;
  }
  if (tried == 0) GTEST_SKIP() << "neither /sys/kernel nor /proc/self is writable to access()";
}

TEST_F(Outputs, AFileSizeLimitLeavesNoTemporaryFile) {
  const CommandRun limited = run_shell("cd " + shell_quote(dir_.string()) + " && ulimit -f 1 && " +
                                       shell_quote(LEVRT_BINARY) +
                                       " render --width 256 --height 256 --quiet --out big.png");
  EXPECT_EQ(limited.exit_code, 1) << limited.output;
  EXPECT_NE(limited.output.find("File too large"), std::string::npos) << limited.output;
  EXPECT_TRUE(entries().empty());
}

TEST_F(Outputs, TheLargestReferenceRenderIsRefusedUpFrontWithinTheMemoryBudget) {
  // Under a 2 GiB address-space limit: a render that tried would die of bad_alloc, exit 1.
  const CommandRun r =
      run_shell(address_space_limit(2097152) + shell_quote(LEVRT_BINARY) +
                " render --width 8192 --height 8192 --subsample 64 --reference rt --stats " +
                shell_quote(path("s.json")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("budget"), std::string::npos) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_TRUE(entries().empty());
}

TEST_F(Outputs, WroteLineNamesEveryFileAndQuietSilencesIt) {
  const CommandRun r = run_levrt({"render", "--width", "8", "--height", "8", "--out", path("a.png"),
                                  "--stats", path("s.json")});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + path("a.png") + ", " + path("s.json") + "\n"),
            std::string::npos)
      << r.output;
  const CommandRun quiet = run_levrt(output_render_args({"--out", path("b.png")}));
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.output, "");
}

TEST_F(Outputs, SubsampledStatsEstimateTheFullFrameTime) {
  const CommandRun r =
      run_levrt(output_render_args({"--subsample", "4", "--stats", path("s.json")}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_file(path("s.json")).find("\"time_render_full_frame_estimate_s\""),
            std::string::npos);
  const CommandRun full = run_levrt(output_render_args({"--stats", path("full.json")}));
  EXPECT_EQ(read_file(path("full.json")).find("time_render_full_frame_estimate_s"),
            std::string::npos);
}

TEST_F(Outputs, NewlinesAndEscapesInNamesAndValuesStayOnOneLine) {
  const std::vector<std::vector<std::string>> cases = {
      {"render", "--method", "lev\nrt"},
      {"render", "--scene", "evil\n\x1b[31mred.json"},
      {"render", "--out", path("a\nb.txt")},
  };
  for (const auto& args : cases) {
    const CommandRun r = run_levrt(args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  }
  const CommandRun escaped = run_levrt({"render", "--scene", "evil\n\x1b[31mred.json"});
  EXPECT_NE(escaped.output.find("evil\\n\\x1b[31mred.json"), std::string::npos) << escaped.output;
}

// A right-to-left override (U+202E) in a name made "evil<RLO>gnp.json" show as "evilnosj.png" on
// a terminal, and a glTF's warnings printed its path raw: every message quotes user text through
// the one escaping (scenes::escape_control_characters), which shows the override as \u202e.
TEST_F(Outputs, RightToLeftOverridesInNamesArePrintedAsEscapes) {
  const std::string rlo = "\u202E";
  const CommandRun missing = run_levrt({"render", "--scene", "evil" + rlo + "gnp.json"});
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_EQ(missing.output.find(rlo), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("evil\\u202egnp.json"), std::string::npos) << missing.output;

  const fs::path folder = dir_ / ("lights" + rlo + "fig");
  fs::create_directories(folder);
  const std::string gltf = (folder / "sun.gltf").string();
  std::ofstream(gltf) << R"({"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_levrt_unknown"],
    "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"translation": [0, 0, 5]}]})";
  const CommandRun warned = run_levrt(
      {"render", "--scene", gltf, "--width", "8", "--height", "8", "--out", path("sun.png")});
  EXPECT_NE(warned.output.find("warning"), std::string::npos) << warned.output;
  EXPECT_EQ(warned.output.find(rlo), std::string::npos) << warned.output;
  EXPECT_NE(warned.output.find("lights\\u202efig"), std::string::npos) << warned.output;
}

TEST_F(Outputs, AMasterNameWithNewlinesAndEscapesIsReportedOnOneLine) {
  const std::string scene = path("cycle.json");
  std::ofstream(scene)
      << R"({"levrt_scene": 1, "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "masters": [{"name": "a\nb\nc\u001b[2J",
                 "node": {"type": "instance", "master": "a\nb\nc\u001b[2J"}}],
    "root": {"type": "instance", "master": "a\nb\nc\u001b[2J"}})";
  const CommandRun r = run_levrt({"render", "--scene", scene, "--width", "8", "--height", "8"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("a\\nb\\nc\\x1b[2J"), std::string::npos) << r.output;
}

TEST_F(Outputs, LightCountsAreReportedAsTyped) {
  for (const std::string typed : {" -1", "99999999999999999999", "+64", "64 "}) {
    const CommandRun r = run_levrt(output_render_args({"--lights", typed}));
    EXPECT_EQ(r.exit_code, 2) << typed;
    EXPECT_NE(r.output.find("got '" + typed + "'"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("18446744073709551615"), std::string::npos) << r.output;
  }
}

TEST_F(Outputs, SceneNumbersAreReportedAsTypedNotAsTheRoundedFloat) {
  const std::string camera = R"("camera": {"position": [0, 1, 5], "target": [0, 0, 0]})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"levrt_scene": 1, )" + camera +
           R"(, "root": {"type": "spot_light", "intensity": [1, 1, 1],
          "cone_degrees": 180.00001, "dropoff": 1}})",
       "(180.00001)"},
      {R"({"levrt_scene": 1, )" + camera + R"(, "root": {"type": "affine", "scale": 1e-50,
          "child": {"type": "union", "children": []}}})",
       "(1e-50)"},
  };
  for (const auto& [text, typed] : cases) {
    const std::string scene = path("typed.json");
    std::ofstream(scene) << text;
    const CommandRun r = run_levrt({"render", "--scene", scene, "--width", "8", "--height", "8"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(typed), std::string::npos) << r.output;
  }
}

TEST_F(Outputs, ANulByteInASceneFileIsAnErrorNamingItsOffset) {
  const std::string scene = path("nul.json");
  const std::string valid =
      R"({"levrt_scene": 1, "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "root": {"type": "union", "children": []}})";
  {
    std::ofstream out(scene, std::ios::binary);
    out << valid << '\0' << "garbage";
  }
  const CommandRun r = run_levrt({"render", "--scene", scene, "--width", "8", "--height", "8"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("NUL byte at offset " + std::to_string(valid.size())), std::string::npos)
      << r.output;
}

TEST_F(Outputs, TooManyJsonValuesAreRefusedWhileParsing) {
  const std::string scene = path("many.json");
  {
    std::ofstream out(scene);
    out << "[";
    for (int i = 0; i < 1'100'000; ++i) out << "{},";
    out << "{}]";
  }
  const CommandRun r = run_shell(address_space_limit(1048576) + shell_quote(LEVRT_BINARY) +
                                 " render --scene " + shell_quote(scene) + " --width 8 --height 8");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("more than 1000000 JSON values"), std::string::npos) << r.output;
}

// A scene file small enough to render in a blink.
const char* const kSceneText =
    R"({"levrt_scene": 1, "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
    "root": {"type": "union", "children": [{"type": "point_light", "intensity": [1, 1, 1]}]}})";

// Every file in the folder with its bytes, to show that nothing changed.
std::map<std::string, std::string> snapshot_of(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    files[name] = e.is_symlink()        ? "-> " + fs::read_symlink(e.path()).string()
                  : e.is_regular_file() ? read_file(e.path())
                                        : "(other)";
  }
  return files;
}

TEST_F(Outputs, AnOutputThatIsTheSceneFileIsRefusedHoweverSpelled) {
  std::ofstream(path("in.json")) << kSceneText;
  fs::create_symlink("in.json", path("link.json"));
  fs::create_directories(dir_ / "sub");
  const auto before = snapshot_of(dir_);
  for (const char* spelled : {"in.json", "./in.json", "sub/../in.json", "link.json"}) {
    const CommandRun r = run_here(output_render_args({"--scene", "in.json", "--stats", spelled}));
    EXPECT_EQ(r.exit_code, 2) << spelled << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find("--stats: names a file this command reads"), std::string::npos)
        << r.output;
    EXPECT_EQ(snapshot_of(dir_), before) << spelled;
  }
  const CommandRun exported = run_here({"export", "--scene", "in.json", "--out", "sub/../in.json"});
  EXPECT_EQ(exported.exit_code, 2) << exported.output;
  EXPECT_EQ(line_count(exported.output), 1) << exported.output;
  EXPECT_EQ(snapshot_of(dir_), before);
}

// The check reads the glTF's URIs before any work, so the file need not even be a valid glTF.
TEST_F(Outputs, AnOutputThatIsAGltfBufferOrTextureIsRefused) {
  fs::create_directories(dir_ / "model");
  std::ofstream(dir_ / "model" / "scene.gltf")
      << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "geometry.png", "byteLength": 4}],
             "images": [{"uri": "base%20colour.png"}, {"uri": "data:image/png;base64,AAAA"},
                        {"uri": "leaf+mask.png"}, {"uri": "sub/../bark.png"}]})";
  std::ofstream(dir_ / "model" / "geometry.png") << "buffer bytes";
  std::ofstream(dir_ / "model" / "base colour.png") << "texture bytes";
  // tinygltf reads '+' in a URI as a space: this texture is the file "leaf mask.png".
  std::ofstream(dir_ / "model" / "leaf mask.png") << "texture bytes";
  // The reader resolves `sub/..` lexically: model/bark.png, though sub leads elsewhere.
  std::ofstream(dir_ / "model" / "bark.png") << "texture bytes";
  fs::create_directories(dir_ / "elsewhere" / "deep");
  fs::create_directory_symlink(fs::path("..") / "elsewhere" / "deep", dir_ / "model" / "sub");
  const auto before = snapshot_of(dir_);
  for (const auto& [flag, name] : std::vector<std::pair<std::string, std::string>>{
           {"--out", "model/base colour.png"},
           {"--heatmap-lights", "model/geometry.png"},
           {"--heatmap-noise", "model/../model/base colour.png"},
           {"--heatmap-nodes", "model/leaf mask.png"},
           {"--heatmap-bound", "model/bark.png"}}) {
    const CommandRun r = run_here(output_render_args({"--scene", "model/scene.gltf", flag, name}));
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(flag + ": names a file this command reads"), std::string::npos)
        << r.output;
    EXPECT_EQ(snapshot_of(dir_), before) << name;
  }
}

// A binary glTF over a JSON scene file's 64 MiB (it may be as large as the glTF budget): its
// texture is an input too. The input list read files of at most 64 MiB whole, so it named none.
TEST_F(Outputs, AnOutputThatIsATextureOfABinaryGltfOverTheSceneFileLimitIsRefused) {
  const std::string json =
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 68157440}],
          "images": [{"uri": "t.png"}]})";
  levrt_test::write_sparse_glb(path("big.glb"), json, "", 68157440);
  std::ofstream(path("t.png")) << "texture bytes";
  const CommandRun r = run_here(output_render_args({"--scene", "big.glb", "--out", "t.png"}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--out: names a file this command reads"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(path("t.png")), "texture bytes");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2);
}

TEST_F(Outputs, AnOutputThatIsAGlbTextureIsRefused) {
  const std::string json = R"({"asset": {"version": "2.0"}, "images": [{"uri": "t.png"}]} )";
  std::string glb = "glTF";
  const auto u32 = [&glb](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) glb += static_cast<char>((v >> (8 * i)) & 0xff);
  };
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + json.size()));
  u32(static_cast<std::uint32_t>(json.size()));
  u32(0x4E4F534A);
  glb += json;
  std::ofstream(path("scene.glb"), std::ios::binary) << glb;
  std::ofstream(path("t.png")) << "texture bytes";
  const auto before = snapshot_of(dir_);
  const CommandRun r = run_here(output_render_args({"--scene", "scene.glb", "--out", "t.png"}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_EQ(snapshot_of(dir_), before);
}

TEST_F(Outputs, ASymlinkLoopIsRefusedWithOneLineAndStaysALink) {
  fs::create_symlink("loop.png", path("loop.png"));
  const CommandRun r = run_here(output_render_args({"--out", "loop.png"}));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--out: is a symlink loop"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_symlink(path("loop.png")));
  EXPECT_EQ(entries(), std::vector<std::string>{"loop.png"});
  fs::create_symlink("loop", path("loop"));
  const CommandRun bench = run_here({"bench", "--suite", "thesis", "--quick", "--out", "loop"});
  EXPECT_EQ(bench.exit_code, 2) << bench.output;
  EXPECT_EQ(line_count(bench.output), 1) << bench.output;
  EXPECT_EQ(entries(), (std::vector<std::string>{"loop", "loop.png"}));
}

// Standard output is a pipe whose reader is gone (`levrt render --out - --stats s.json | true`):
// the write fails with one line naming it, exit 1, and the stats, staged beside, are not left as a
// temporary file. Before, SIGPIPE killed the process (exit 141) with the temporary behind. The read
// end is closed before levrt starts, so the write always meets a broken pipe.
TEST_F(Outputs, StandardOutputWithoutAReaderLeavesNoTemporaryFile) {
  const std::string stats = path("s.json");
  const std::string messages = path("messages.txt");
  const int status = levrt_test::run_levrt_into_closed_pipe(
      {"render", "--width", "64", "--height", "48", "--quiet", "--out", "-", "--stats", stats},
      messages);
  ASSERT_NE(status, -1);
  const std::string output = read_file(messages);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ": " << output;
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_EQ(line_count(output), 1) << output;
  EXPECT_NE(output.find("write to standard output failed (Broken pipe)"), std::string::npos)
      << output;
  EXPECT_EQ(entries(), std::vector<std::string>{"messages.txt"});
}

// A FIFO output nobody opens for reading: levrt waits for a reader once every other output is
// staged, and Ctrl-C still ends it (exit 130, one line, the staged stats removed, the FIFO kept).
// Before, it waited in open() with the termination signals blocked: only SIGKILL ended it, and
// that left the temporary behind. The signal is sent once the stats' temporary exists, so levrt
// is in the write by then; 60 s without an exit is the hang.
TEST_F(Outputs, CtrlCEndsTheWaitForAFifoReaderAndLeavesNoTemporary) {
  ASSERT_EQ(::mkfifo(path("pipe.png").c_str(), 0600), 0);
  const std::string out = path("pipe.png"), stats = path("s.json"), messages = path("log.txt");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int log = ::open(messages.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    const char* binary = LEVRT_BINARY;
    ::execl(binary, binary, "render", "--width", "8", "--height", "8", "--quiet", "--out",
            out.c_str(), "--stats", stats.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto staged = [this] {
    for (const std::string& name : entries())
      if (name.rfind(".levrt-", 0) == 0) return true;
    return false;
  };
  int status = 0;
  bool exited = false;
  for (int step = 0; step < 60000 && !staged() && !exited; ++step) {
    exited = ::waitpid(child, &status, WNOHANG) == child;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_FALSE(exited) << "levrt ended before writing: " << read_file(messages);
  ::kill(child, SIGINT);
  for (int step = 0; step < 60000 && !exited; ++step) {
    exited = ::waitpid(child, &status, WNOHANG) == child;
    if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (!exited) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
    ADD_FAILURE() << "levrt ignored Ctrl-C while it waited for the FIFO's reader";
  }
  const std::string output = read_file(messages);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << status << ": " << output;
  EXPECT_EQ(line_count(output), 1) << output;
  EXPECT_NE(output.find("interrupted"), std::string::npos) << output;
  EXPECT_TRUE(fs::is_fifo(path("pipe.png")));
  EXPECT_EQ(entries(), (std::vector<std::string>{"log.txt", "pipe.png"}));
}

// A UNIX socket cannot be opened as a file: refused before rendering, one line, exit 2 (open()
// fails with ENXIO, which a FIFO without a reader also gives; that one is waited for).
TEST_F(Outputs, ASocketOutputIsRefusedBeforeRendering) {
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(sock, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string name = path("sock.png");
  if (name.size() >= sizeof(address.sun_path)) GTEST_SKIP() << "folder name too long for a socket";
  std::copy(name.begin(), name.end(), address.sun_path);
  ASSERT_EQ(::bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  // Bounded: a levrt that took the socket's ENXIO for a FIFO without a reader would wait forever.
  const CommandRun r =
      run_shell("cd " + shell_quote(dir_.string()) + " && timeout 60 " + shell_quote(LEVRT_BINARY) +
                " render --width 8 --height 8 --quiet --out sock.png");
  ::close(sock);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--out: is a socket"), std::string::npos) << r.output;
  EXPECT_EQ(entries(), std::vector<std::string>{"sock.png"});
}

// A block device (a disk or partition; here a node of a loop device, made in the test's folder) is
// never written in place, named directly or through a symlink: writing a PNG there would
// overwrite the start of the disk. Making a device node needs root (CAP_MKNOD).
TEST_F(Outputs, ABlockDeviceIsRefusedBeforeRenderingAndStaysADevice) {
  if (::mknod(path("disk.png").c_str(), S_IFBLK | 0600, makedev(7, 250)) != 0)
    GTEST_SKIP() << "cannot make a device node here (needs root)";
  fs::create_symlink("disk.png", path("link.png"));
  for (const std::string name : {"disk.png", "link.png"}) {
    for (const std::string flag : {"--out", "--stats", "--heatmap-lights"}) {
      const std::string file = flag == "--stats" ? name.substr(0, 4) + ".json" : name;
      if (flag == "--stats" && !fs::exists(path(file))) fs::create_symlink("disk.png", path(file));
      const CommandRun r = run_here(output_render_args({flag, file}));
      EXPECT_EQ(r.exit_code, 2) << flag << " " << file << ": " << r.output;
      EXPECT_EQ(line_count(r.output), 1) << r.output;
      EXPECT_NE(r.output.find(flag + ": is a block device"), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("'" + file + "'"), std::string::npos) << r.output;
    }
  }
  struct stat st {};
  ASSERT_EQ(::stat(path("disk.png").c_str(), &st), 0);
  EXPECT_TRUE(S_ISBLK(st.st_mode));
  EXPECT_EQ(st.st_rdev, makedev(7, 250));
  EXPECT_EQ(entries(),
            (std::vector<std::string>{"disk.json", "disk.png", "link.json", "link.png"}));
  const CommandRun exported =
      run_here({"export", "--scene", "maze", "--level", "1", "--out", "disk.json"});
  EXPECT_EQ(exported.exit_code, 2) << exported.output;
  EXPECT_NE(exported.output.find("--out: is a block device"), std::string::npos) << exported.output;
}

// A character device other than /dev/null, /dev/zero, /dev/full and terminals (/dev/port,
// /dev/kmsg, a CPU's msr, a watchdog) is never written in place. The node made here is autofs's
// control device (10:235), which refuses writes anyway: before, the render ran and then failed.
TEST_F(Outputs, ACharacterDeviceOtherThanNullZeroFullOrATerminalIsRefusedBeforeRendering) {
  if (::mknod(path("misc.png").c_str(), S_IFCHR | 0600, makedev(10, 235)) != 0)
    GTEST_SKIP() << "cannot make a device node here (needs root)";
  fs::create_symlink("misc.png", path("misc.json"));
  for (const auto& [flag, file] : std::vector<std::pair<std::string, std::string>>{
           {"--out", "misc.png"}, {"--stats", "misc.json"}, {"--heatmap-nodes", "misc.png"}}) {
    const CommandRun r = run_here(output_render_args({flag, file}));
    EXPECT_EQ(r.exit_code, 2) << flag << " " << file << ": " << r.output;
    EXPECT_EQ(line_count(r.output), 1) << r.output;
    EXPECT_NE(r.output.find(flag + ": is a device levrt does not write"), std::string::npos)
        << r.output;
  }
  struct stat st {};
  ASSERT_EQ(::stat(path("misc.png").c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_EQ(st.st_rdev, makedev(10, 235));
  EXPECT_EQ(run_here(output_render_args({"--stats", "/dev/null"})).exit_code, 0);
}

// A 64 KiB tmpfs holds the first outputs but not all: the render fails with one line, every old
// file stays as it was and no temporary is left. Mounting needs root (or a user namespace).
TEST_F(Outputs, AFullFileSystemWritesNoOutputAndKeepsTheOldFiles) {
  const fs::path full = dir_ / "full";
  fs::create_directories(full);
  const CommandRun mounted =
      run_shell("mount -t tmpfs -o size=64k levrt_outputs_test " + shell_quote(full.string()));
  if (mounted.exit_code != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (needs root): " << mounted.output;
  }
  struct Unmount {
    fs::path at;
    ~Unmount() { run_shell("umount " + shell_quote(at.string())); }
  } unmount{full};
  std::ofstream(full / "image.png") << "old image";
  std::ofstream(full / "stats.json") << "old stats";
  const auto before = snapshot_of(full);
  // Every output of one render, each in `folder`.
  const auto render_into = [](const fs::path& folder) {
    return run_levrt({"render",
                      "--width",
                      "192",
                      "--height",
                      "144",
                      "--spp",
                      "2",
                      "--quiet",
                      "--out",
                      (folder / "image.png").string(),
                      "--heatmap-lights",
                      (folder / "lights.png").string(),
                      "--heatmap-nodes",
                      (folder / "nodes.png").string(),
                      "--heatmap-bound",
                      (folder / "bound.png").string(),
                      "--heatmap-noise",
                      (folder / "noise.png").string(),
                      "--stats",
                      (folder / "stats.json").string()});
  };
  const CommandRun r = render_into(full);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(snapshot_of(full), before);
  // The same render fits on a roomy file system: the failure was the space, not the outputs.
  const CommandRun roomy = render_into(fs::path(path("image.png")).parent_path());
  EXPECT_EQ(roomy.exit_code, 0) << roomy.output;
  std::uintmax_t total = 0;
  for (const char* f :
       {"image.png", "lights.png", "nodes.png", "bound.png", "noise.png", "stats.json"})
    total += fs::file_size(path(f));
  EXPECT_GT(total, 64u * 1024u) << "the outputs must overflow the 64 KiB file system";
  EXPECT_LT(fs::file_size(path("image.png")), 48u * 1024u) << "the first output must fit";
}

// A render the budget allows but the address space does not: one line and exit 1, not an abort.
TEST_F(Outputs, OutOfMemoryIsOneLineAndExitOne) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no ulimit -v under it";
#endif
  const CommandRun r =
      run_shell(address_space_limit(786432) + shell_quote(LEVRT_BINARY) +
                " render --width 4096 --height 4096 --subsample 64 --quiet --out " +
                shell_quote(path("i.png")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("levrt: error: out of memory"), std::string::npos) << r.output;
  EXPECT_TRUE(entries().empty());
}

TEST_F(Outputs, HelpListsEverySettingsDefaultAndRange) {
  const CommandRun r = run_levrt({"render", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  const app::Settings defaults;
  for (const app::SettingSpec& spec : app::setting_table()) {
    const std::string flag = std::string("--") + spec.name + " ";
    const std::size_t at = r.output.find(flag);
    ASSERT_NE(at, std::string::npos) << flag << "\n" << r.output;
    const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
    EXPECT_NE(line.find("=" + app::setting_text(defaults, spec)), std::string::npos) << line;
    if (const auto* range = std::get_if<app::IntRange>(&spec.kind)) {
      EXPECT_NE(
          line.find("[" + std::to_string(range->min) + ", " + std::to_string(range->max) + "]"),
          std::string::npos)
          << line;
    } else if (const auto* choice = std::get_if<app::Choice>(&spec.kind)) {
      for (const std::string& option : choice->options())
        EXPECT_NE(line.find(option), std::string::npos) << line;
    } else {
      EXPECT_NE(line.find("FLOAT"), std::string::npos) << line;
    }
  }
}

TEST_F(Outputs, AnUnknownCommandListsTheCommands) {
  const CommandRun r = run_levrt({"rendr"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  for (const std::string command : {"render", "export", "bench", "snapshot", "view"}) {
    EXPECT_NE(r.output.find(command), std::string::npos) << r.output;
  }
}

TEST_F(Outputs, WithoutADisplayLevrtSaysItWritesTheSnapshotAndWhere) {
  // stderr alone: the summary on stdout goes to /dev/null.
  const CommandRun r = run_shell("(cd " + shell_quote(dir_.string()) + " && env -u DISPLAY " +
                                 shell_quote(LEVRT_BINARY) + " 2>&1 >/dev/null)");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find((fs::canonical(dir_) / "out").string()), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "building.png"));
}

// The folder the snapshot would go to is the working folder's: a right-to-left override in its
// name was printed raw in the "no display" line. (A file named out ends the run before it renders.)
TEST_F(Outputs, WithoutADisplayTheSnapshotFolderIsPrintedEscaped) {
  const fs::path here = dir_ / "work\u202Eing";
  fs::create_directories(here);
  std::ofstream(here / "out") << "the user's notes";
  const CommandRun r = run_shell("(cd " + shell_quote(here.string()) + " && env -u DISPLAY " +
                                 shell_quote(LEVRT_BINARY) + " 2>&1)");
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("\u202E"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("work\\u202eing/out instead"), std::string::npos) << r.output;
}

// The snapshot's folder "out" named by a file or a dangling symlink: one line naming it, exit 2,
// and the file or link left as it was (it was exit 1, "filesystem error: cannot create
// directories").
TEST_F(Outputs, ASnapshotWhoseOutIsNotAFolderIsRefusedAndLeavesIt) {
  std::ofstream(path("out")) << "the user's notes";
  const CommandRun file = run_here({"snapshot"});
  EXPECT_EQ(file.exit_code, 2) << file.output;
  EXPECT_EQ(line_count(file.output), 1) << file.output;
  EXPECT_NE(file.output.find("snapshot: cannot make the folder 'out'"), std::string::npos)
      << file.output;
  EXPECT_EQ(read_file(path("out")), "the user's notes");
  fs::remove(path("out"));
  fs::create_symlink("missing/folder", path("out"));
  const CommandRun link = run_here({"snapshot"});
  EXPECT_EQ(link.exit_code, 2) << link.output;
  EXPECT_EQ(line_count(link.output), 1) << link.output;
  EXPECT_TRUE(fs::is_symlink(path("out")));
  EXPECT_EQ(entries(), std::vector<std::string>{"out"});
}

// An existing output the user may not write is refused before rendering and kept: read-only for
// a user, immutable (chattr +i) for root, whom permissions do not stop. Before, the render ran
// and its rename replaced a read-only file, or failed on the immutable one with exit 1.
TEST_F(Outputs, AnExistingOutputThatIsNotWritableIsRefusedBeforeRenderingAndKept) {
  std::ofstream(path("kept.png")) << "old image";
  const bool root = ::geteuid() == 0;
  if (root) {
    if (run_shell("chattr +i " + shell_quote(path("kept.png")) + " 2>/dev/null").exit_code != 0)
      GTEST_SKIP() << "chattr +i is not available here";
  } else {
    fs::permissions(path("kept.png"), fs::perms::owner_read);
  }
  const CommandRun r = run_here(output_render_args({"--out", "kept.png"}));
  if (root) run_shell("chattr -i " + shell_quote(path("kept.png")));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(line_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--out: is not writable, got 'kept.png'"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(path("kept.png")), "old image");
  EXPECT_EQ(entries(), std::vector<std::string>{"kept.png"});
}

}  // namespace
