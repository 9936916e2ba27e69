// The pixel inspector in the real viewer window under Xvfb, in scripted mode: `inspect=X,Y`
// opens the inspector window and marks the top contributors on the
// image in the marker colour, which no other drawing uses; selecting a row (`inspect_row=N`) adds
// its extent volume's outline; `inspect=off` clears it all; pixels pinned, changed and cleared
// frame after frame, one pending at exit, end with exit 0. Skipped only when Xvfb is missing.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/png_file.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"
#include "tests/support/xvfb_server.h"

namespace {

namespace fs = std::filesystem;

using Png = levrt_test::PngImage;

Png read_png(const fs::path& path) {
  return levrt_test::read_png_image(path);
}

// Pixels of about the inspector's marker colour (app/viewer/inspector_panel.h: 255, 0, 255).
int marker_pixels(const Png& png) {
  int count = 0;
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
    count += png.rgb[i] > 200 && png.rgb[i + 1] < 80 && png.rgb[i + 2] > 200;
  }
  return count;
}

int differences(const Png& a, const Png& b) {
  if (a.rgb.size() != b.rgb.size()) return -1;
  int count = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    count += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
  }
  return count;
}

TEST(InspectorWindow, ScriptedInspectOpensThePanelAndMarksTheTopContributors) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const levrt_test::TempDir dir("levrt-inspector-window-");
  const auto path = [&](const std::string& name) { return (dir.path() / name).string(); };
  // clang-format off
  const levrt_test::CommandRun run = levrt_test::run_viewer_on_xvfb({
      "--scene", "building", "--lights", "64", "--width", "128", "--height", "96", "--spp", "1",
      "--tolerance", "0.05", "--window", "1280x800", "--frames", "12",
      "--set", "await=idle@0",
      "--set", "screenshot=" + path("before.png") + "@1",
      "--set", "inspect=64,60@2",
      "--set", "await=idle@3",
      "--set", "screenshot=" + path("pinned.png") + "@5",
      "--set", "inspect_row=0@6",
      "--set", "screenshot=" + path("row.png") + "@8",
      "--set", "inspect=off@9",
      "--set", "screenshot=" + path("cleared.png") + "@11",
  });
  // clang-format on
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const Png before = read_png(path("before.png")), pinned = read_png(path("pinned.png"));
  const Png row = read_png(path("row.png")), cleared = read_png(path("cleared.png"));
  ASSERT_TRUE(before.width > 0 && pinned.width > 0 && row.width > 0 && cleared.width > 0);
  EXPECT_EQ(marker_pixels(before), 0);
  EXPECT_GT(marker_pixels(pinned), 20) << "no contributor marked";
  EXPECT_GT(differences(before, pinned), 1000) << "no inspector window";
  EXPECT_GT(differences(pinned, row), 20) << "no extent outline for the selected row";
  EXPECT_EQ(marker_pixels(cleared), 0);
}

// Pinning pixels frame after frame, changing the method and clearing while an inspection may
// still run, then quitting with one pending: each replaces or cancels the last, and the session
// ends with exit 0 (a pending inspection does not hold the exit).
TEST(InspectorWindow, InspectionsReplacedClearedAndPendingAtExitEndWithExitZero) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  // clang-format off
  const levrt_test::CommandRun run = levrt_test::run_viewer_on_xvfb({
      "--scene", "hall", "--lights", "4096", "--width", "64", "--height", "48", "--spp", "4",
      "--window", "800x600", "--frames", "6",
      "--set", "inspect=32,24@1",
      "--set", "inspect=10,40@2",
      "--set", "method=lightcuts@3",
      "--set", "inspect=off@3",
      "--set", "inspect=50,5@4",
      "--set", "inspect=20,20@5",
  });
  // clang-format on
  EXPECT_EQ(run.exit_code, 0) << run.output;
}

TEST(InspectorWindow, BadInspectValuesAreRefusedWithOneLine) {
  for (const char* change : {"inspect=a,b@1", "inspect=5@1", "inspect_row=x@1"}) {
    const levrt_test::CommandRun run =
        levrt_test::run_levrt({"view", "--frames", "2", "--set", change});
    EXPECT_EQ(run.exit_code, 2) << change << ": " << run.output;
    EXPECT_NE(run.output.find("inspect"), std::string::npos) << run.output;
  }
}

}  // namespace
