// The one writer (app/output_files.h): a PNG is written whole through a temporary that is renamed
// onto the target; several outputs are written all or none (an encoder that fails, a folder that
// is missing or a rename that fails leaves every old file as it was and no temporary); the
// outputs' rule refuses an output that is an input or another output, however spelled.
#include "app/output_files.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "app/settings.h"
#include "tests/support/read_file.h"
#include "tests/support/temp_dir.h"

namespace {

using levrt_test::read_file;
namespace fs = std::filesystem;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::function<std::string()> text(const std::string& t) {
  return [t] { return t; };
}

TEST(OutputFiles, WritesCompleteFileAndLeavesNoTemporary) {
  const levrt_test::TempDir temp("levrt_output_files_test_");
  const std::filesystem::path& dir = temp.path();
  const std::string path = (dir / "a.png").string();
  app::write_png_rgb8(path, 2, 1, {255, 0, 0, 0, 255, 0});
  EXPECT_GT(std::filesystem::file_size(path), 8u);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.png"});
  EXPECT_THROW(app::write_png_rgb8((dir / "missing" / "b.png").string(), 2, 1, {0, 0, 0, 0, 0, 0}),
               std::runtime_error);
  EXPECT_THROW(app::write_png_rgb8(path, 3, 1, {0, 0, 0}), std::invalid_argument);
}

TEST(OutputFiles, AReplacedFileKeepsItsPermissionBits) {
  const levrt_test::TempDir temp("levrt_output_files_mode_");
  const fs::path dir = temp.path();
  const fs::path private_file = dir / "private.json";
  const fs::path shared_file = dir / "shared.png";
  { std::ofstream(private_file) << "old"; }
  { std::ofstream(shared_file) << "old"; }
  fs::permissions(private_file, fs::perms::owner_read | fs::perms::owner_write);
  fs::permissions(shared_file, fs::perms::owner_read | fs::perms::owner_write |
                                   fs::perms::group_read | fs::perms::group_write |
                                   fs::perms::others_read | fs::perms::others_write);
  app::write_output_files(
      {{private_file.string(), text("new")}, {shared_file.string(), text("new too")}});
  EXPECT_EQ(read_file(private_file), "new");
  EXPECT_EQ(read_file(shared_file), "new too");
  const auto bits = [](const fs::path& p) { return fs::status(p).permissions() & fs::perms::mask; };
  EXPECT_EQ(bits(private_file), fs::perms::owner_read | fs::perms::owner_write)
      << "a private file stays private";
  EXPECT_EQ(bits(shared_file), fs::perms::owner_read | fs::perms::owner_write |
                                   fs::perms::group_read | fs::perms::group_write |
                                   fs::perms::others_read | fs::perms::others_write);
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"private.json", "shared.png"}));
}

TEST(OutputFiles, AnEncoderThatFailsLeavesEveryOldFile) {
  const levrt_test::TempDir temp("levrt_output_files_encoder_");
  const fs::path& dir = temp.path();
  std::ofstream(dir / "a.txt") << "old a";
  std::ofstream(dir / "b.txt") << "old b";
  EXPECT_THROW(app::write_output_files({{(dir / "a.txt").string(), text("new a")},
                                        {(dir / "c.txt").string(), text("new c")},
                                        {(dir / "b.txt").string(),
                                         []() -> std::string { throw std::runtime_error("no"); }}}),
               std::runtime_error);
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(read_file(dir / "b.txt"), "old b");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputFiles, AMissingFolderForTheLastOutputWritesNone) {
  const levrt_test::TempDir temp("levrt_output_files_folder_");
  const fs::path& dir = temp.path();
  std::ofstream(dir / "a.txt") << "old a";
  try {
    app::write_output_files({{(dir / "a.txt").string(), text("new a")},
                             {(dir / "missing" / "b.txt").string(), text("new b")}});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/b.txt: cannot write (No such file"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"a.txt"});
}

// A rename that fails (onto a folder) after an earlier one succeeded puts the earlier file back.
TEST(OutputFiles, ARenameThatFailsPutsBackTheFilesRenamedBeforeIt) {
  const levrt_test::TempDir temp("levrt_output_files_rename_");
  const fs::path& dir = temp.path();
  std::ofstream(dir / "a.txt") << "old a";
  fs::create_directories(dir / "folder" / "inside");
  EXPECT_THROW(app::write_output_files({{(dir / "a.txt").string(), text("new a")},
                                        {(dir / "new.txt").string(), text("new")},
                                        {(dir / "folder").string(), text("never")}}),
               std::runtime_error);
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "folder"}));
}

TEST(OutputFiles, AllOutputsAreWrittenTogether) {
  const levrt_test::TempDir temp("levrt_output_files_all_");
  const fs::path& dir = temp.path();
  std::ofstream(dir / "a.txt") << "old a";
  app::write_output_files(
      {{(dir / "a.txt").string(), text("new a")}, {(dir / "b.txt").string(), text("new b")}});
  EXPECT_EQ(read_file(dir / "a.txt"), "new a");
  EXPECT_EQ(read_file(dir / "b.txt"), "new b");
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputFiles, AnOutputThatIsAnInputIsRefusedHoweverSpelled) {
  const levrt_test::TempDir temp("levrt_output_files_input_");
  const fs::path& dir = temp.path();
  std::ofstream(dir / "in.json") << "{}";
  fs::create_symlink(dir / "in.json", dir / "link.json");
  fs::create_hard_link(dir / "in.json", dir / "hard.json");
  fs::create_directories(dir / "sub");
  for (const fs::path& spelled :
       {dir / "in.json", dir / "link.json", dir / "hard.json", dir / "sub" / ".." / "in.json"}) {
    try {
      app::check_output_paths({{"--stats", spelled.string(), ".json", "JSON"}},
                              {(dir / "in.json").string()});
      ADD_FAILURE() << spelled << " was accepted";
    } catch (const app::UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--stats: names a file this command reads"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(app::check_output_paths(
      {{"--stats", (dir / "other.json").string(), ".json", "JSON"}}, {(dir / "in.json").string()}));
  EXPECT_EQ(read_file(dir / "in.json"), "{}");
}

TEST(OutputFiles, ASymlinkLoopIsRefusedByTheCheckAndTheWriter) {
  const levrt_test::TempDir temp("levrt_output_files_loop_");
  const fs::path& dir = temp.path();
  fs::create_symlink(dir / "b.png", dir / "a.png");
  fs::create_symlink(dir / "a.png", dir / "b.png");
  EXPECT_THROW(app::check_output_paths({{"--out", (dir / "a.png").string(), ".png", "PNG"}}),
               app::UsageError);
  EXPECT_THROW(app::write_text_file((dir / "a.png").string(), "x"), std::runtime_error);
  EXPECT_TRUE(fs::is_symlink(dir / "a.png"));
  EXPECT_TRUE(fs::is_symlink(dir / "b.png"));
  EXPECT_EQ(entries(dir), (std::vector<std::string>{"a.png", "b.png"}));
}

TEST(OutputFiles, ADeviceIsWrittenInPlace) {
  if (!fs::is_character_file("/dev/null")) GTEST_SKIP() << "no /dev/null";
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  app::write_output_files({{"/dev/null", text("bytes")}});
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_rdev, before.st_rdev);
  EXPECT_EQ(after.st_ino, before.st_ino);
}

// A block device is refused by the check (a UsageError naming the flag) and by the writer itself,
// which never opens it. Making a device node needs root (CAP_MKNOD).
TEST(OutputFiles, ABlockDeviceIsRefusedByTheCheckAndTheWriter) {
  const levrt_test::TempDir temp("levrt_output_files_block_");
  const fs::path disk = temp.path() / "disk.png";
  if (::mknod(disk.c_str(), S_IFBLK | 0600, makedev(7, 251)) != 0)
    GTEST_SKIP() << "cannot make a device node here (needs root)";
  try {
    app::check_output_paths({{"--out", disk.string(), ".png", "PNG"}});
    ADD_FAILURE() << "a block device was accepted as an output";
  } catch (const app::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--out: is a block device"), std::string::npos)
        << e.what();
  }
  try {
    app::write_output_files({{disk.string(), text("bytes")}});
    ADD_FAILURE() << "a block device was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a block device"), std::string::npos) << e.what();
  }
  struct stat st {};
  ASSERT_EQ(::stat(disk.c_str(), &st), 0);
  EXPECT_TRUE(S_ISBLK(st.st_mode));
  EXPECT_EQ(entries(temp.path()), std::vector<std::string>{"disk.png"});
}

TEST(OutputFiles, PublishingAStagingFolderFollowsTheRule) {
  const levrt_test::TempDir temp("levrt_output_files_publish_");
  const fs::path& dir = temp.path();
  fs::create_directories(dir / "out" / ".staging");
  std::ofstream(dir / "out" / ".staging" / "results.md") << "new results";
  std::ofstream(dir / "out" / ".staging" / "a.csv") << "new csv";
  fs::create_directories(dir / "elsewhere");
  fs::create_symlink(dir / "elsewhere" / "a.csv", dir / "out" / "a.csv");
  app::publish_staging_folder((dir / "out" / ".staging").string(), (dir / "out").string());
  EXPECT_EQ(read_file(dir / "out" / "results.md"), "new results");
  EXPECT_TRUE(fs::is_symlink(dir / "out" / "a.csv"));
  EXPECT_EQ(read_file(dir / "elsewhere" / "a.csv"), "new csv");
  EXPECT_EQ(entries(dir / "out"), (std::vector<std::string>{"a.csv", "results.md"}));
}

TEST(OutputFiles, TheWriterRefusesACharacterDeviceOtherThanNullZeroFullOrATerminal) {
  const levrt_test::TempDir temp("levrt_output_files_chr_");
  const std::string misc = (temp.path() / "misc.json").string();
  if (::mknod(misc.c_str(), S_IFCHR | 0600, makedev(10, 235)) != 0)
    GTEST_SKIP() << "cannot make a device node here (needs root)";
  const std::string kept = (temp.path() / "kept.json").string();
  EXPECT_THROW(app::write_output_files({{kept, text("new")}, {misc, text("{}")}}),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(kept)) << "all or none";
  EXPECT_THROW(app::check_output_paths({{"--stats", misc, ".json", "JSON"}}), app::UsageError);
  EXPECT_NO_THROW(app::check_output_paths({{"--stats", "/dev/full", ".json", "JSON"}}));
}

}  // namespace
