#include "app/exr_encoding.h"

#include <tinyexr.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/support/exr_file.h"
#include "tests/support/gltf_files.h"

namespace {
namespace fs = std::filesystem;

std::vector<glm::vec3> test_colours(int width, int height) {
  std::vector<glm::vec3> colours;
  for (int i = 0; i < width * height; ++i) {
    const float v = static_cast<float>(i);
    colours.emplace_back(v * 0.125f, 1e-7f * v, 12345.678f + v);
  }
  colours[1] = glm::vec3(std::numeric_limits<float>::infinity(), -2.5f, 1e30f);
  return colours;
}

// LoadEXR (tinyexr's RGBA reader) reads back exactly the floats written, top row first.
TEST(ExrEncoding, RoundTripReadsBackTheFloats) {
  const int width = 5, height = 3;
  const std::vector<glm::vec3> colours = test_colours(width, height);
  const std::string bytes = app::exr_bytes(width, height, app::rgb_channels(colours));
  const fs::path path =
      fs::temp_directory_path() / ("levrt_exr_" + std::to_string(::getpid()) + ".exr");
  levrt_test::write_file(path, bytes);
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* error = nullptr;
  ASSERT_EQ(LoadEXR(&rgba, &w, &h, path.c_str(), &error), TINYEXR_SUCCESS) << (error ? error : "");
  fs::remove(path);
  ASSERT_EQ(w, width);
  ASSERT_EQ(h, height);
  for (int i = 0; i < width * height; ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(rgba[4 * i + c], colours[static_cast<std::size_t>(i)][c]) << i << " " << c;
  }
  std::free(rgba);
}

TEST(ExrEncoding, FurtherChannelsKeepTheirNamesAndValues) {
  std::vector<app::ExrChannel> channels = app::rgb_channels(test_colours(4, 2));
  channels.push_back({"lights_tested", {0, 1, 2, 3, 4, 5, 6, 7.5f}});
  channels.push_back({"error_pct", {9, 8, 7, 6, 5, 4, 3, 2}});
  const levrt_test::ExrFile file = levrt_test::read_exr(app::exr_bytes(4, 2, channels));
  EXPECT_EQ(file.width, 4);
  EXPECT_EQ(file.height, 2);
  ASSERT_EQ(file.channels.size(), 5u);
  EXPECT_EQ(file.channels.at("lights_tested"), channels[3].values);
  EXPECT_EQ(file.channels.at("error_pct"), channels[4].values);
  EXPECT_EQ(file.channels.at("G"), channels[1].values);
}

TEST(ExrEncoding, MismatchedOrDuplicateChannelsAreRefused) {
  EXPECT_THROW(app::exr_bytes(2, 2, {{"R", {1, 2, 3}}}), std::invalid_argument);
  EXPECT_THROW(app::exr_bytes(1, 1, {{"R", {1}}, {"R", {2}}}), std::invalid_argument);
  EXPECT_THROW(app::exr_bytes(0, 1, {{"R", {}}}), std::invalid_argument);
  EXPECT_THROW(app::exr_bytes(1, 1, {}), std::invalid_argument);
}

}  // namespace
