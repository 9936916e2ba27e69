// A fresh folder for one test, made by mkdtemp and removed with everything in it at the end. A
// fixed name under /tmp collides when ctest runs tests in parallel or when release, asan and tsan
// builds run their suites at the same time; mkdtemp's random suffix keeps every run apart.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace levrt_test {

class TempDir {
 public:
  // The folder is <temp>/<prefix>XXXXXX; prefix names the test so a left-over folder says whose.
  explicit TempDir(const std::string& prefix) {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace levrt_test
