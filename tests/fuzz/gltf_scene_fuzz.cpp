// libFuzzer target over the glTF reader (scenes/gltf_scene.h): any byte string, read as .glb when
// its first byte is odd and as .gltf otherwise, must either become a valid description or be
// refused with std::invalid_argument, never crash, hang or leak. Built by the `fuzz` preset.
// The budget is 16 MiB, not the gigabyte a render allows: every check still runs, and a valid
// scene near the budget builds in well under libFuzzer's -timeout under ASan + UBSan (at 1 GiB
// such a scene took 9 s of CPU, 50 s on a loaded machine: docs/extremes.md).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scenes/gltf_scene.h"

namespace {
constexpr std::uint64_t kFuzzBudgetBytes = std::uint64_t{16} << 20;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string path = (data[0] & 1u) != 0 ? "fuzz.glb" : "fuzz.gltf";
  try {
    (void)scenes::parse_gltf_scene(std::string(reinterpret_cast<const char*>(data + 1), size - 1),
                                   path, 0, kFuzzBudgetBytes);
  } catch (const std::invalid_argument&) {
    // Refusing bad input with a message is the expected outcome.
  }
  return 0;
}
