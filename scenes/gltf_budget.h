// The one memory budget of a glTF scene: every byte the import will hold is charged before it is
// allocated, and the first charge past kMaxGltfSceneBytes refuses the file with one line naming
// the file, what was charged and the budget. Charged, in this order: the file and its JSON
// document (per value), the external buffers and images by their size on disk (before they are
// read), then, before anything is built, every texture as decoded (its texels, read from the
// image's header; once per texture that uses an image) and every triangle primitive as built
// (its vertices and triangles, counted per primitive, so an accessor reused by forty primitives is
// charged forty times). So a refused file allocates no more than what it was charged up to the
// refusal, which is at most its own size and its JSON; an accepted scene's peak memory follows
// the budget's sum (docs/extremes.md measures both).
#pragma once

#include <cstdint>
#include <string>

namespace scenes {

inline constexpr std::uint64_t kMaxGltfSceneBytes = std::uint64_t{1} << 30;
// Costs per unit, the slopes of peak RSS of `levrt render` (docs/extremes.md, "glTF memory
// budget"): a texel 24 bytes (the RGB floats, their 8-bit decode and the renderer's copy); a
// built vertex 48 and a triangle 120 (reading, the mesh, Embree's copy and its BVH); a JSON value
// as nlohmann holds it, as for scene files. So the largest texture alone is about 6,600 x 6,600.
inline constexpr std::uint64_t kGltfBytesPerTexel = 24;
inline constexpr std::uint64_t kGltfBytesPerVertex = 48;
inline constexpr std::uint64_t kGltfBytesPerTriangle = 120;
inline constexpr std::uint64_t kGltfBytesPerJsonValue = 110;

class GltfBudget {
 public:
  GltfBudget(const std::string& path, std::uint64_t limit_bytes)
      : path_(path), limit_bytes_(limit_bytes) {}

  // Adds `bytes`, or throws std::invalid_argument "PATH: WHAT: N bytes ..., past the budget"
  // when the sum would exceed the limit. `bytes` saturates: any count times a cost is safe.
  void charge(std::uint64_t bytes, const std::string& what);
  // count * unit_bytes, saturating.
  void charge(std::uint64_t count, std::uint64_t unit_bytes, const std::string& what);

  std::uint64_t used_bytes() const { return used_bytes_; }
  std::uint64_t limit_bytes() const { return limit_bytes_; }

 private:
  const std::string& path_;
  std::uint64_t limit_bytes_;
  std::uint64_t used_bytes_ = 0;
};

}  // namespace scenes
