// A GoogleTest fixture with a fresh folder of its own (tests/support/temp_dir.h: mkdtemp, so
// parallel runs and the release, asan and tsan suites never share one), named after the test
// and removed with everything in it afterwards. dir_ is the folder, path(name) a file in it.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace levrt_test {

class FolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = std::make_unique<TempDir>(
        "levrt_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
        "_");
    dir_ = folder_->path();
  }
  void TearDown() override { folder_.reset(); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;

 private:
  std::unique_ptr<TempDir> folder_;
};

}  // namespace levrt_test
