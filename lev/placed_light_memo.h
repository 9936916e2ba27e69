// A memo of the light made from a placed subtree: a subtree's node and the frame it is entered
// with (rotation, scale, translation) fix the representative lev_cut's walk makes of it and the
// light its cluster's shadow ray goes to, and neighbouring shading points ask for the same
// subtrees again and again (hall 16,384: making them was a quarter of lev_cut's instructions).
// Direct-mapped and per thread (in the walk's scratch): an entry is used only for the same node
// and the same frame bit for bit, and the light is a function of those alone, so what is found is
// what would be made; images do not depend on the memo, its size or the order points come in.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include <glm/glm.hpp>

#include "lev/light.h"

namespace lev {

class PlacedLightMemo {
 public:
  // Entries: a power of two. 1,024 hold the subtrees of a tile's points at hall 16,384.
  static constexpr std::size_t kEntries = 4096;

  // Makes the memo serve the hierarchy and node table identified by these (their arrays'
  // addresses): what it holds for others is forgotten (a scratch reused with another hierarchy).
  void serve(const void* hierarchy, const void* table) {
    if (hierarchy == hierarchy_ && table == table_) return;
    hierarchy_ = hierarchy;
    table_ = table;
    for (Entry& entry : entries_) entry.filled = false;
  }

  // The light make() gives for (node, rotation, scale, translation), made once per entry.
  template <typename Make>
  const Light& find_or_make(std::uint32_t node, const glm::mat3& rotation, float scale,
                            const glm::vec3& translation, Make&& make) {
    Key key;
    key[0] = node;
    std::memcpy(&key[1], &rotation, 9 * sizeof(float));
    std::memcpy(&key[10], &scale, sizeof(float));
    std::memcpy(&key[11], &translation, 3 * sizeof(float));
    if (entries_.empty()) entries_.resize(kEntries);
    Entry& entry = entries_[slot(key)];
    if (!entry.filled || entry.key != key) {
      entry.light = make();
      entry.key = key;
      entry.filled = true;
    }
    return entry.light;
  }

 private:
  using Key = std::array<std::uint32_t, 14>;
  struct Entry {
    Key key{};
    bool filled = false;
    Light light;
  };
  static std::size_t slot(const Key& key) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const std::uint32_t word : key) {
      h ^= word;
      h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h >> 32) & (kEntries - 1);
  }
  std::vector<Entry> entries_;
  const void* hierarchy_ = nullptr;
  const void* table_ = nullptr;
};

}  // namespace lev
