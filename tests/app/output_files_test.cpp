// Output files: a PNG is written whole through a temporary that is renamed onto the target, and
// a failed write leaves nothing behind.
#include "app/output_files.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace {

TEST(OutputFiles, WritesCompleteFileAndLeavesNoTemporary) {
  const levrt_test::TempDir temp("levrt_output_files_test_");
  const std::filesystem::path& dir = temp.path();
  const std::string path = (dir / "a.png").string();
  app::write_png_rgb8(path, 2, 1, {255, 0, 0, 0, 255, 0});
  EXPECT_GT(std::filesystem::file_size(path), 8u);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  EXPECT_THROW(app::write_png_rgb8((dir / "missing" / "b.png").string(), 2, 1, {0, 0, 0, 0, 0, 0}),
               std::runtime_error);
  EXPECT_THROW(app::write_png_rgb8(path, 3, 1, {0, 0, 0}), std::invalid_argument);
}

}  // namespace
