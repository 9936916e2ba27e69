// Ctrl-C (SIGINT) and SIGTERM during a render or a bench run: levrt stops, exits 130 and leaves
// no file behind (and a bench run leaves an existing results folder as it was). That it stopped
// at the signal is read from its interrupted line, which names the stage it stopped in (loading
// the scene, pass k of n with its tiles done), never from how long it took.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/signal_process.h"
#include "tests/support/slow_gltf.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;

using levrt_test::interrupt_after;
using levrt_test::InterruptedRun;
using levrt_test::InterruptedStage;

// True when the interrupted line says the command stopped before its render ended: while loading
// the scene, or inside a pass (setting up the method, or with tiles of the pass still to do).
bool stopped_before_the_render_ended(const InterruptedStage& stage) {
  if (stage.doing == "loading the scene") return stage.step >= 1 && stage.step <= stage.steps;
  if (stage.doing.rfind("rendering ", 0) != 0) return false;
  return stage.step >= 1 && stage.step <= stage.steps &&
         (stage.tiles == 0 || stage.tiles_done < stage.tiles);
}

InterruptedRun interrupt_render_after(int signal_number, std::chrono::milliseconds delay,
                                      const fs::path& dir) {
  return levrt_test::interrupt_and_read(
      {LEVRT_BINARY, "render", "--lights", "16384", "--method", "rt", "--width", "640", "--height",
       "480", "--spp", "4", "--out", (dir / "i.png").string(), "--stats", (dir / "s.json").string(),
       "--heatmap-lights", (dir / "l.png").string()},
      signal_number, delay);
}

TEST(Interrupt, SignalDuringRenderLeavesNoOutput) {
  for (int sig : {SIGINT, SIGTERM}) {
    for (int delay_ms : {0, 600}) {  // as the scene build starts, during the render
      const levrt_test::TempDir temp("levrt_interrupt_" + std::to_string(sig) + "_" +
                                     std::to_string(delay_ms) + "_");
      const fs::path& dir = temp.path();
      const InterruptedRun run =
          interrupt_render_after(sig, std::chrono::milliseconds(delay_ms), dir);
      EXPECT_EQ(run.exit_code, 130) << "signal " << sig << " after " << delay_ms << " ms\n"
                                    << run.errors;
      EXPECT_TRUE(stopped_before_the_render_ended(levrt_test::interrupted_stage(run.errors)))
          << "signal " << sig << " after " << delay_ms << " ms\n"
          << run.errors;
      EXPECT_TRUE(fs::is_empty(dir)) << "signal " << sig << " after " << delay_ms << " ms";
    }
  }
}

// A glass box reflecting and refracting with weight 1 at every hit (kr = kt = 1) at depth 64: a
// tree of 2^64 rays per pixel, so its one pass never ends. Before the cancel was read inside tiles
// and the recursion, such a render ignored SIGINT and SIGTERM for minutes. It now stops inside
// that pass, with tiles left to do.
TEST(Interrupt, SignalDuringADepthBombStopsInsideItsPass) {
  const levrt_test::TempDir temp("levrt_interrupt_depth_bomb_");
  const fs::path& dir = temp.path();
  fs::create_directories(dir / "out");
  const fs::path scene = dir / "bomb.json";
  std::ofstream(scene)
      << R"({"levrt_scene": 1, "camera": {"position": [0, -10, 5], "target": [0, 0, 0]},
    "materials": [{"name": "bomb", "kd": 0.1, "kr": 1, "kt": 1, "ior": 1.5}],
    "root": {"type": "union", "children": [
      {"type": "box", "material": "bomb", "lo": [-3, -3, 0], "hi": [3, 3, 4]},
      {"type": "affine", "translate": [1, -2, 6],
       "child": {"type": "point_light", "intensity": [20, 20, 20]}}]}})";
  for (int sig : {SIGINT, SIGTERM}) {
    const InterruptedRun run = levrt_test::interrupt_and_read(
        {LEVRT_BINARY, "render", "--scene", scene.string(), "--depth", "64", "--width", "64",
         "--height", "48", "--out", (dir / "out" / "i.png").string()},
        sig, std::chrono::seconds(1));
    EXPECT_EQ(run.exit_code, 130) << "signal " << sig << "\n" << run.errors;
    const InterruptedStage stage = levrt_test::interrupted_stage(run.errors);
    EXPECT_EQ(stage.doing, "rendering lev") << run.errors;
    EXPECT_EQ(stage.step, 1) << run.errors;
    EXPECT_TRUE(stopped_before_the_render_ended(stage)) << run.errors;
    EXPECT_TRUE(fs::is_empty(dir / "out")) << "signal " << sig;
  }
}

// A million lights (building level 10) at tolerance 0: lev's walk returns every light and AST ranks
// and shadow-tests every light, so one shading point takes up to a second and the frame hours.
// The cancel is read inside those light loops (every kCancelCheckLights lights), so the run stops
// inside its first pass.
TEST(Interrupt, SignalDuringAMillionLightRenderStopsInsideItsFirstPass) {
  const levrt_test::TempDir temp("levrt_interrupt_million_lights_");
  const fs::path& dir = temp.path();
  for (const char* method : {"lev", "ast"}) {
    const InterruptedRun run = levrt_test::interrupt_and_read(
        {LEVRT_BINARY, "render", "--scene", "building", "--lights", "1048576", "--method", method,
         "--tolerance", "0", "--width", "320", "--height", "240", "--out",
         (dir / "i.png").string()},
        SIGINT, std::chrono::seconds(1));
    EXPECT_EQ(run.exit_code, 130) << method << "\n" << run.errors;
    EXPECT_TRUE(stopped_before_the_render_ended(levrt_test::interrupted_stage(run.errors)))
        << method << "\n"
        << run.errors;
    EXPECT_TRUE(fs::is_empty(dir)) << method;
  }
}

// A scene that takes seconds to load (tests/support/slow_gltf.h), signalled once its buffer is
// read (the load's long steps have begun): a signal during the load ends
// it there (between its steps, or by the load watchdog in a step that cannot stop) with 130 and
// nothing written. A command that finished the load first would name a later stage.
TEST(Interrupt, SignalDuringTheSceneLoadStopsTheLoadWithNothingWritten) {
  const levrt_test::TempDir temp("levrt_interrupt_load_");
  const fs::path scene = levrt_test::write_slow_loading_gltf(temp.path());
  const fs::path dir = temp.path() / "out";
  fs::create_directories(dir);
  for (int sig : {SIGINT, SIGTERM}) {
    EXPECT_EQ(levrt_test::interrupted_while(
                  {LEVRT_BINARY, "render", "--scene", scene.string(), "--width", "32", "--height",
                   "24", "--out", (dir / "i.png").string(), "--stats", (dir / "s.json").string()},
                  sig, std::chrono::milliseconds(100),
                  [](pid_t pid) {
                    return levrt_test::has_read_at_least(pid, levrt_test::kSlowGltfBufferBytes);
                  }),
              "loading the scene")
        << "signal " << sig;
    EXPECT_TRUE(fs::is_empty(dir)) << "signal " << sig;
  }
}

// `levrt inspect` installed no handlers: SIGINT and SIGTERM killed it (no line, no exit 130), and
// once it had traced the pixel a signal was not looked at again, so the minutes of formatting a
// million lights' lists ran on and wrote them. Now it stops as render does, in the load, the
// inspection or the formatting, with nothing written (the JSON, the table on standard output).
TEST(Interrupt, SignalDuringInspectStopsItWithNothingWritten) {
  const levrt_test::TempDir temp("levrt_interrupt_inspect_");
  const fs::path& dir = temp.path();
  for (int sig : {SIGINT, SIGTERM}) {
    for (int delay_ms : {0, 1500}) {  // as the scene loads; formatting the lists
      const InterruptedRun run = levrt_test::interrupt_and_read(
          {LEVRT_BINARY, "inspect", "--scene", "building", "--lights", "1048576", "--method", "rt",
           "--pixel", "160,120", "--json", (dir / "pixel.json").string()},
          sig, std::chrono::milliseconds(delay_ms));
      EXPECT_EQ(run.exit_code, 130) << "signal " << sig << " after " << delay_ms << " ms\n"
                                    << run.errors;
      EXPECT_TRUE(levrt_test::interrupted_stage(run.errors).found) << run.errors;
      EXPECT_TRUE(fs::is_empty(dir)) << "signal " << sig << " after " << delay_ms << " ms";
    }
  }
}

TEST(Interrupt, SignalDuringBenchLeavesNoOutputAndKeepsEarlierResults) {
  const levrt_test::TempDir temp("levrt_interrupt_bench_");
  const fs::path& dir = temp.path();
  fs::create_directories(dir / "kept");
  { std::ofstream(dir / "kept" / "results.md") << "an earlier run"; }
  for (int delay_ms : {0, 1500}) {  // while the scenes are planned, and during the renders
    for (const char* out : {"new", "kept"}) {
      const fs::path out_dir = dir / out;
      EXPECT_EQ(interrupt_after({LEVRT_BINARY, "bench", "--suite", "thesis", "--quick", "--out",
                                 out_dir.string()},
                                SIGINT, std::chrono::milliseconds(delay_ms)),
                130)
          << out << " after " << delay_ms << " ms";
    }
    EXPECT_FALSE(fs::exists(dir / "new")) << "after " << delay_ms << " ms";
    std::vector<fs::path> kept;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "kept"))
      kept.push_back(e.path().filename());
    ASSERT_EQ(kept.size(), 1u) << "after " << delay_ms << " ms";
    std::ifstream in(dir / "kept" / "results.md");
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "an earlier run");
  }
}

TEST(Interrupt, SignalDuringBenchRemovesEveryFolderItMade) {
  const levrt_test::TempDir temp("levrt_interrupt_bench_folders_");
  const fs::path& dir = temp.path();
  for (int delay_ms : {0, 1500}) {
    EXPECT_EQ(interrupt_after({LEVRT_BINARY, "bench", "--suite", "thesis", "--quick", "--out",
                               (dir / "made" / "below" / "results").string()},
                              SIGINT, std::chrono::milliseconds(delay_ms)),
              130)
        << "after " << delay_ms << " ms";
    EXPECT_TRUE(fs::is_empty(dir))
        << "after " << delay_ms << " ms: " << (fs::exists(dir / "made") ? "made/ left" : "");
  }
}

}  // namespace
