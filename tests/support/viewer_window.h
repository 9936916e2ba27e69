// What the viewer-window tests (tests/viewer/viewer_window_test.cpp, viewer_refusal_test.cpp)
// share: the fixture with its own temporary folder, running the viewer on a private Xvfb, and
// reading back what it wrote (PNG pixels, JSON, folder contents, device nodes).
#pragma once

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "tests/support/folder_test.h"
#include "tests/support/gltf_files.h"
#include "tests/support/png_file.h"
#include "tests/support/run_command.h"
#include "tests/support/signal_process.h"
#include "tests/support/slow_gltf.h"
#include "tests/support/trade_report.h"
#include "tests/support/xvfb_server.h"

namespace levrt_test {

namespace fs = std::filesystem;

inline CommandRun run_viewer(const std::vector<std::string>& args) {
  return run_viewer_on_xvfb(args);
}

using Png = PngImage;

inline Png read_png(const fs::path& path) {
  return read_png_image(path);
}

inline bool uniform(const Png& png) {
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        if (png.at(x, y)[c] != png.at(0, 0)[c]) return false;
      }
    }
  }
  return true;
}

// Pixels that differ inside the picture (right of the panel, above the statistics).
inline int picture_differences(const Png& a, const Png& b) {
  int differences = 0;
  for (int y = a.height * 15 / 100; y < a.height * 55 / 100; ++y) {
    for (int x = a.width / 2; x < a.width * 9 / 10; ++x) {
      if (a.at(x, y)[0] != b.at(x, y)[0] || a.at(x, y)[1] != b.at(x, y)[1] ||
          a.at(x, y)[2] != b.at(x, y)[2]) {
        ++differences;
      }
    }
  }
  return differences;
}

inline std::string read_file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(read_file_bytes(path), nullptr, false);
}

// The viewer's "not rendered yet" grey (app/viewer/display_image.h, kNotRenderedRgb).
inline int not_rendered_pixels(const Png& png) {
  int count = 0;
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      const unsigned char* p = png.at(x, y);
      if (p[0] == 38 && p[1] == 38 && p[2] == 42) ++count;
    }
  }
  return count;
}

class ViewerWindow : public levrt_test::FolderTest {};

using levrt_test::line_count;

// Every file in the folder with its bytes (or its kind), to show that nothing changed.
inline std::map<std::string, std::string> files_in(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    files[fs::relative(e.path(), dir).string()] =
        e.is_regular_file() ? read_file_bytes(e.path()) : "(not a regular file)";
  }
  return files;
}

// The device node stays the same device: never replaced by a regular file.
inline void expect_same_device(const char* device, const struct stat& before) {
  struct stat after {};
  ASSERT_EQ(::stat(device, &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << device;
  EXPECT_EQ(after.st_rdev, before.st_rdev) << device;
  EXPECT_EQ(after.st_ino, before.st_ino) << device;
}

}  // namespace levrt_test
