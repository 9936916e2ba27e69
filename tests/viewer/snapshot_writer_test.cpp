// The snapshot writer's refusals that the window tests cannot reach through a script: an empty
// folder (the panel's field cleared) is refused with a message saying so; and a snapshot whose
// name is taken is written beside the files there, never over them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "app/viewer/snapshot_writer.h"
#include "tests/support/temp_dir.h"

namespace {

TEST(SnapshotWriter, AnEmptyFolderIsRefusedSayingSo) {
  app::viewer::SnapshotWriter writer;
  app::viewer::SnapshotJob job;
  job.folder = "";
  job.base = "view";
  job.width = 1;
  job.height = 1;
  job.image_rgb = {0, 0, 0};
  job.heatmap_rgb = {0, 0, 0};
  job.heatmap_name = "lights";
  job.stats_json = "{}\n";
  ASSERT_TRUE(writer.start(job));
  writer.wait();
  EXPECT_TRUE(writer.failed());
  EXPECT_EQ(writer.message(), "snapshot failed: no folder given (the folder field is empty)");
}

std::string snapshot_file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Two snapshots of the same method and tolerance (an orbit, a new relative error between them)
// share the panel's name: the second replaced the first. Now it is _2, then _3; a file of any
// kind under one of the four names (the stats a --camera-from read) is kept too.
TEST(SnapshotWriter, ATakenNameGetsANumberAndNoFileIsReplaced) {
  const levrt_test::TempDir dir("levrt_snapshot_names_");
  app::viewer::SnapshotJob job;
  job.folder = dir.path().string();
  job.base = "view_building_64_lev_0.01";
  job.width = 1;
  job.height = 1;
  job.image_rgb = {1, 2, 3};
  job.heatmap_rgb = {4, 5, 6};
  job.heatmap_name = "lights";
  job.stats_json = "{\"first\": true}\n";
  job.exr_channels = {{"R", {0.5f}}};
  app::viewer::SnapshotWriter writer;
  ASSERT_TRUE(writer.start(job));
  writer.wait();
  ASSERT_FALSE(writer.failed()) << writer.message();
  const auto stats = [&](const std::string& stem) {
    return snapshot_file_text(dir.path() / (stem + "_stats.json"));
  };
  EXPECT_EQ(stats("view_building_64_lev_0.01"), job.stats_json);

  job.stats_json = "{\"second\": true}\n";
  ASSERT_TRUE(writer.start(job));
  writer.wait();
  ASSERT_FALSE(writer.failed()) << writer.message();
  EXPECT_EQ(stats("view_building_64_lev_0.01"), "{\"first\": true}\n");
  EXPECT_EQ(stats("view_building_64_lev_0.01_2"), job.stats_json);
  EXPECT_NE(writer.message().find("view_building_64_lev_0.01_2.png"), std::string::npos)
      << writer.message();

  // Only the EXR's name is taken (by a file that is no snapshot): the next number again.
  std::ofstream(dir.path() / "view_building_64_lev_0.01_3.exr") << "kept";
  ASSERT_TRUE(writer.start(job));
  writer.wait();
  ASSERT_FALSE(writer.failed()) << writer.message();
  EXPECT_EQ(snapshot_file_text(dir.path() / "view_building_64_lev_0.01_3.exr"), "kept");
  EXPECT_EQ(stats("view_building_64_lev_0.01_4"), job.stats_json);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "view_building_64_lev_0.01_3.png"));
}

}  // namespace
