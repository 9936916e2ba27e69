#include "scenes/scene_inputs.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scenes/gltf_scene.h"
#include "scenes/scene_file.h"

namespace scenes {
namespace {

using json = nlohmann::json;

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

// The whole file when it is a regular file within the scene-file limit; of a larger binary glTF
// (which may be as large as the glTF budget), its 20-byte header and a JSON chunk within that
// limit; else empty.
std::string read_small_regular_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return {};
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return {};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {};
  std::string bytes(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 20)), '\0');
  bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
  std::uintmax_t wanted = size;
  if (size > kMaxSceneFileBytes) {
    const bool glb = bytes.size() == 20 && bytes.compare(0, 4, "glTF") == 0;
    const std::uint32_t json_bytes = glb ? little_endian_u32(bytes, 12) : 0;
    wanted = glb && json_bytes <= kMaxSceneFileBytes ? 20 + std::uintmax_t{json_bytes} : 0;
  }
  if (wanted > bytes.size()) {
    const std::size_t have = bytes.size();
    bytes.resize(static_cast<std::size_t>(wanted));
    bytes.resize(have + std::fread(bytes.data() + have, 1, bytes.size() - have, f));
  } else if (wanted == 0) {
    bytes.clear();
  }
  std::fclose(f);
  return bytes;
}

// The JSON chunk of a GLB file (glTF 2.0, section "Binary glTF Layout"), or empty.
std::string glb_json_chunk(const std::string& bytes) {
  constexpr std::size_t kHeaderBytes = 12, kChunkHeaderBytes = 8;
  constexpr std::uint32_t kJsonChunkType = 0x4E4F534A;  // "JSON"
  if (bytes.size() < kHeaderBytes + kChunkHeaderBytes || bytes.compare(0, 4, "glTF") != 0)
    return {};
  const std::uint32_t length = little_endian_u32(bytes, kHeaderBytes);
  if (little_endian_u32(bytes, kHeaderBytes + 4) != kJsonChunkType ||
      length > bytes.size() - kHeaderBytes - kChunkHeaderBytes) {
    return {};
  }
  return bytes.substr(kHeaderBytes + kChunkHeaderBytes, length);
}

// Collects the strings at /buffers/N/uri and /images/N/uri, keeping only the path of open
// containers (never the values), so depth and size cost nothing but the stack of keys.
class UriCollector {
 public:
  std::vector<std::string> uris;

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t) { return true; }
  bool number_float(json::number_float_t, const json::string_t&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool string(json::string_t& value) {
    if (at_uri()) uris.push_back(value);
    return true;
  }
  bool start_object(std::size_t) {
    open_.push_back({true, {}});
    return true;
  }
  bool start_array(std::size_t) {
    open_.push_back({false, {}});
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& name) {
    if (!open_.empty()) open_.back().key = open_.size() <= 3 ? name : std::string();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) {
    return false;
  }

 private:
  struct Container {
    bool object;
    std::string key;  // the member being read (kept only near the root, where it matters)
  };

  bool close() {
    if (!open_.empty()) open_.pop_back();
    return true;
  }
  bool at_uri() const {
    return open_.size() == 3 && open_[0].object &&
           (open_[0].key == "buffers" || open_[0].key == "images") && !open_[1].object &&
           open_[2].object && open_[2].key == "uri";
  }

  std::vector<Container> open_;
};

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// As tinygltf decodes a URI before it opens the file (scene_folder.h's uri_file_path): percent
// escapes, and '+' read as a space.
std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 &&
               hex_value(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> scene_input_files(const std::string& path) {
  if (!is_scene_file_name(path)) return {};
  std::vector<std::string> files = {path};
  if (!is_gltf_file_name(path)) return files;
  const std::string bytes = read_small_regular_file(path);
  const std::string text = bytes.compare(0, 4, "glTF") == 0 ? glb_json_chunk(bytes) : bytes;
  UriCollector collector;
  json::sax_parse(text, &collector, json::input_format_t::json, false);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const std::string& uri : collector.uris) {
    if (uri.empty() || uri.rfind("data:", 0) == 0) continue;
    for (const std::string& name : {uri, percent_decoded(uri)}) {
      files.push_back((folder / name).string());
      // The reader resolves a URI's `..` lexically (scene_folder.h), against the name before it
      // whatever symlink that is: "sub/../t.png" is the folder's t.png, where the kernel would
      // go up from sub's target.
      files.push_back((folder / std::filesystem::path(name).lexically_normal()).string());
    }
  }
  return files;
}

}  // namespace scenes
