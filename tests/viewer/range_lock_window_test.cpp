// The heatmap range lock (`--set range_lock=on`, the legend's lock) in snapshots, in the real
// viewer window under Xvfb: a snapshot of a locked view draws its heatmap over the locked range
// and reports that range in its stats, byte for byte what `levrt render --heatmap-range LO,HI`
// writes for the same settings; unlocked, the snapshot keeps its own range. Skipped without Xvfb.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/folder_test.h"
#include "tests/support/png_file.h"
#include "tests/support/read_file.h"
#include "tests/support/run_command.h"
#include "tests/support/xvfb_server.h"

namespace {

namespace fs = std::filesystem;

class RangeLockWindow : public levrt_test::FolderTest {
 protected:
  // The file of a snapshot folder whose name ends with `suffix`.
  fs::path snapshot_file(const std::string& folder, const std::string& suffix) const {
    for (const auto& entry : fs::directory_iterator(dir_ / folder)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        return entry.path();
    }
    return {};
  }
  nlohmann::json stats(const std::string& folder) const {
    return nlohmann::json::parse(levrt_test::read_file(snapshot_file(folder, "_stats.json")),
                                 nullptr, false);
  }
};

TEST_F(RangeLockWindow, ASnapshotOfALockedViewUsesTheLockedRangeAsRenderHeatmapRangeDoes) {
  if (!levrt_test::have_xvfb())
    GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): viewer test skipped";
  const std::vector<std::string> settings = {"--scene", "building", "--lights", "64",    "--width",
                                             "64",      "--height", "48",       "--spp", "1"};
  std::vector<std::string> args = settings;
  // clang-format off
  for (const std::string& a : std::vector<std::string>{
           "--tolerance", "0.3", "--window", "1024x640", "--frames", "12",
           "--set", "view=lights@0",
           "--set", "await=idle@1",
           "--set", "snapshot=" + path("coarse") + "@2",
           "--set", "screenshot=" + path("shown.png") + "@3",  // composes the range it locks
           "--set", "range_lock=on@4",
           "--set", "tolerance=0.001@5",
           "--set", "await=idle@6",
           "--set", "snapshot=" + path("locked") + "@7",
           "--set", "range_lock=off@8",
           "--set", "snapshot=" + path("unlocked") + "@9"})
    args.push_back(a);
  // clang-format on
  const levrt_test::CommandRun view = levrt_test::run_viewer_on_xvfb(args);
  ASSERT_EQ(view.exit_code, 0) << view.output;
  const nlohmann::json coarse = stats("coarse"), locked = stats("locked");
  const nlohmann::json unlocked = stats("unlocked");
  ASSERT_TRUE(coarse.is_object() && locked.is_object() && unlocked.is_object()) << view.output;
  const nlohmann::json range = coarse["heatmap_lights_range"];
  ASSERT_TRUE(range.is_array()) << coarse.dump();
  // Locked at the coarse tolerance's range; unlocked, the finer tolerance's own (more lights).
  EXPECT_EQ(locked["heatmap_lights_range"], range);
  EXPECT_NE(unlocked["heatmap_lights_range"], range);
  EXPECT_GT(unlocked["heatmap_lights_range"][1].get<double>(), range[1].get<double>());
  const levrt_test::PngImage locked_png =
      levrt_test::read_png_image(snapshot_file("locked", "_lights.png"));
  const levrt_test::PngImage unlocked_png =
      levrt_test::read_png_image(snapshot_file("unlocked", "_lights.png"));
  ASSERT_EQ(locked_png.width, 64);
  EXPECT_NE(locked_png.rgb, unlocked_png.rgb);

  // The headless render of the same settings over the same range draws the same heatmap.
  char range_text[96];
  std::snprintf(range_text, sizeof range_text, "%.17g,%.17g", range[0].get<double>(),
                range[1].get<double>());
  std::vector<std::string> render = {"render"};
  render.insert(render.end(), settings.begin(), settings.end());
  for (const std::string& a :
       {std::string("--tolerance"), std::string("0.001"), std::string("--heatmap-lights"),
        path("headless.png"), std::string("--heatmap-range"), std::string(range_text)})
    render.push_back(a);
  const levrt_test::CommandRun headless = levrt_test::run_levrt(render);
  ASSERT_EQ(headless.exit_code, 0) << headless.output;
  EXPECT_EQ(levrt_test::read_png_image(path("headless.png")).rgb, locked_png.rgb);
}

}  // namespace
