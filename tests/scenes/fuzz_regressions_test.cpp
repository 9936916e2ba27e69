// Replays every input kept in tests/fuzz/regressions/ (crashes the fuzzer once found, and hostile
// shapes written by hand): each must be refused with a message or read cleanly.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "scenes/scene_file.h"

namespace {

TEST(FuzzRegressions, EveryKeptInputIsRefusedOrReadCleanly) {
  const std::filesystem::path dir =
      std::filesystem::path(LEVRT_SOURCE_DIR) / "tests" / "fuzz" / "regressions";
  std::size_t inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    try {
      (void)scenes::parse_scene_json(bytes.str(), entry.path().filename().string());
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(entry.path().filename().string()), std::string::npos)
          << e.what();
    }
    ++inputs;
  }
  EXPECT_GE(inputs, 4u);
}

}  // namespace
