// A glTF scene that takes seconds to load, for tests that signal a command during its load: one
// mesh of eight primitives, each reading the same 200,000 scattered triangles from an external
// buffer (each primitive is built on its own, so the geometry and its ray-tracing hierarchy are
// built eight times). Measured here: 9.5 s to render in a Release build (3 primitives: 3.1 s, and
// 13 s under AddressSanitizer), so a command that waited for the load is told apart from one that
// stopped within the tests' 5 s even on a loaded machine, where 3 primitives and 2 s failed once
// (the viewer under asan at a load of 6). The load is dominated by steps that cannot poll the
// cancel flag, so a signal there is ended by the load watchdog. (The generated scene models load
// in well under a second since their lights and geometry are instanced, so they no longer serve
// this purpose.)
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace levrt_test {

// The size of slow.bin: a process has begun the load's long steps once it has read this much
// (signal_process.h's has_read_at_least; it reads the buffer whole, then builds for seconds).
inline constexpr unsigned long long kSlowGltfBufferBytes = 200000ull * 9 * sizeof(float);

// Writes slow.gltf and slow.bin into `dir` and returns the path of slow.gltf.
inline std::filesystem::path write_slow_loading_gltf(const std::filesystem::path& dir) {
  constexpr int kTriangles = 200000;
  constexpr int kPrimitives = 8;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> centre(-10.0f, 10.0f);
  std::uniform_real_distribution<float> offset(-0.1f, 0.1f);
  std::vector<float> positions;
  positions.reserve(kTriangles * 9);
  for (int t = 0; t < kTriangles; ++t) {
    const float c[3] = {centre(random), centre(random), centre(random)};
    for (int vertex = 0; vertex < 3; ++vertex) {
      for (float axis : c) positions.push_back(axis + offset(random));
    }
  }
  const std::uint64_t bytes = positions.size() * sizeof(float);
  static_assert(kSlowGltfBufferBytes == kTriangles * 9 * sizeof(float), "slow.bin's size");
  std::ofstream(dir / "slow.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(positions.data()), static_cast<std::streamsize>(bytes));
  std::string primitives;
  for (int p = 0; p < kPrimitives; ++p)
    primitives += std::string(p ? "," : "") + R"({"attributes": {"POSITION": 0}})";
  const std::filesystem::path gltf = dir / "slow.gltf";
  std::ofstream(gltf) << R"({"asset": {"version": "2.0"},
    "buffers": [{"uri": "slow.bin", "byteLength": )"
                      << bytes << R"(}],
    "bufferViews": [{"buffer": 0, "byteLength": )"
                      << bytes << R"(}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )"
                      << kTriangles * 3 << R"(,
                   "min": [-10.1, -10.1, -10.1], "max": [10.1, 10.1, 10.1]}],
    "meshes": [{"primitives": [)"
                      << primitives << R"(]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
  return gltf;
}

}  // namespace levrt_test
