// Hostile glTF files for tests, written as text into a test's folder: a triangle scene whose
// parts a test replaces (buffers, images, textures, materials, meshes, nodes), a PNG of zeros of
// any size, and the one-line refusal check for a file on disk (load_scene_file).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "scenes/scene_file.h"

namespace levrt_test {

// One triangle's positions (0,0,0), (1,0,0), (0,1,0) as a buffer of 36 bytes.
inline const std::string kTriangleBufferUri =
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

// A file drawing mesh 0 from node 0; `parts` are more top-level members (`"meshes": [...]`...).
inline std::string gltf_document(const std::string& parts) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], )" + parts + "}";
}

// Buffer 0 (the triangle, or `uri` of `bytes`), its view and accessor 0 (the three positions).
inline std::string triangle_buffers(const std::string& uri = kTriangleBufferUri,
                                    std::uint64_t bytes = 36) {
  return R"("buffers": [{"byteLength": )" + std::to_string(bytes) + R"(, "uri": ")" + uri +
         R"("}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3}])";
}

inline std::string triangle_scene() {
  return gltf_document(triangle_buffers() + R"(, "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}])");
}

// A grey PNG of width x height zeros: a few hundred KB that decode to width x height texels.
inline std::string zero_png(int width, int height) {
  const std::vector<unsigned char> zeros(static_cast<std::size_t>(width) *
                                         static_cast<std::size_t>(height));
  std::string png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
      },
      &png, width, height, 1, zeros.data(), width);
  return png;
}

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// A binary glTF of `json` and a BIN chunk of `bin_bytes` (a multiple of 4) that starts with
// `bin_head`; the rest of the chunk is a hole, so a file of many megabytes costs no disk.
inline void write_sparse_glb(const std::filesystem::path& path, std::string json,
                             const std::string& bin_head, std::uint32_t bin_bytes) {
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string head;
  const auto u32 = [&head](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) head += static_cast<char>((v >> (8 * i)) & 0xffu);
  };
  const auto json_bytes = static_cast<std::uint32_t>(json.size());
  head += "glTF";
  u32(2);
  u32(12 + 8 + json_bytes + 8 + bin_bytes);
  u32(json_bytes);
  u32(0x4E4F534Au);
  head += json;
  u32(bin_bytes);
  u32(0x004E4942u);
  head += bin_head;
  std::ofstream out(path, std::ios::binary);
  out << head;
  out.seekp(static_cast<std::streamoff>(head.size() - bin_head.size() + bin_bytes - 1));
  out.put('\0');
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// Loading `path` throws one line starting "PATH: " and holding every one of `problems`;
// returns the line.
inline std::string expect_load_refused(const std::filesystem::path& path,
                                       const std::vector<std::string>& problems) {
  try {
    scenes::load_scene_file(path.string());
    ADD_FAILURE() << path << " accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    for (const std::string& problem : problems)
      EXPECT_NE(message.find(problem), std::string::npos) << problem << " in: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  return {};
}

}  // namespace levrt_test
