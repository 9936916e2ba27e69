// libFuzzer target over the scene-file reader: any byte string must either parse into a valid
// description or be refused with std::invalid_argument, never crash, hang or leak. Built by the
// `fuzz` preset (clang, ASan + UBSan); CI runs it for a bounded time from a corpus of the
// exported built-in scenes, and every crash input found is kept in tests/fuzz/regressions/,
// which the scenes test suite replays.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scenes/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const scenes::SceneDescription scene =
        scenes::parse_scene_json(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    // Writing back what was read exercises the exact float printing and the validator again.
    (void)scenes::scene_file_json(scene);
  } catch (const std::invalid_argument&) {
    // Refusing bad input with a message is the expected outcome.
  }
  return 0;
}
