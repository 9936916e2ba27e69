// libFuzzer target over the glTF reader (scenes/gltf_scene.h): any byte string, read as .glb when
// its first byte is odd and as .gltf otherwise, must either become a valid description or be
// refused with std::invalid_argument, never crash, hang or leak. Built by the `fuzz` preset.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "scenes/gltf_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string path = (data[0] & 1u) != 0 ? "fuzz.glb" : "fuzz.gltf";
  try {
    (void)scenes::parse_gltf_scene(std::string(reinterpret_cast<const char*>(data + 1), size - 1),
                                   path);
  } catch (const std::invalid_argument&) {
    // Refusing bad input with a message is the expected outcome.
  }
  return 0;
}
