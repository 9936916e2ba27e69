// The snapshot writer's refusals that the window tests cannot reach through a script: an empty
// folder (the panel's field cleared) is refused with a message saying so.
#include <gtest/gtest.h>

#include <string>

#include "app/viewer/snapshot_writer.h"

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

}  // namespace
