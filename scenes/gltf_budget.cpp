#include "scenes/gltf_budget.h"

#include <limits>
#include <stdexcept>

#include "scenes/scene_folder.h"

namespace scenes {

void GltfBudget::charge(std::uint64_t bytes, const std::string& what) {
  if (bytes > limit_bytes_ - used_bytes_) {
    throw std::invalid_argument(path_ + ": " + what + ": " + std::to_string(bytes) +
                                " bytes on top of the " + std::to_string(used_bytes_) +
                                " already charged exceed the scene's memory budget of " +
                                byte_limit_text(limit_bytes_));
  }
  used_bytes_ += bytes;
}

void GltfBudget::charge(std::uint64_t count, std::uint64_t unit_bytes, const std::string& what) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  charge(unit_bytes != 0 && count > kMax / unit_bytes ? kMax : count * unit_bytes, what);
}

}  // namespace scenes
