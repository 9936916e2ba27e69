#include "scenes/gltf_document.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "scenes/scene_file.h"

namespace scenes {
namespace {

using json = nlohmann::json;

constexpr std::uint64_t kMaxIndex = 2147483647;                  // tinygltf keeps indices in int
constexpr std::uint64_t kMaxByteCount = std::uint64_t{1} << 53;  // exact in a double

// Fields holding an index (alone, or as the elements of an array of indices).
bool is_index_field(std::string_view name) {
  static constexpr std::string_view kNames[] = {
      "scene",   "nodes",  "children",   "mesh",     "camera",
      "skin",    "buffer", "bufferView", "material", "indices",
      "index",   "source", "sampler",    "light",    "node",
      "input",   "output", "joints",     "skeleton", "inverseBindMatrices",
      "texCoord"};
  for (const std::string_view known : kNames) {
    if (name == known) return true;
  }
  return false;
}

bool is_byte_count_field(std::string_view name) {
  return name == "byteOffset" || name == "byteLength" || name == "byteStride" || name == "count";
}

// A JSON number as the checks need it: its sign, whether it is whole, and its magnitude.
struct Number {
  bool negative = false;
  bool whole = true;
  std::uint64_t magnitude = 0;  // exact for integers, saturated for huge floats
  std::string text;
};

std::string shortened(const std::string& text, std::size_t max_length) {
  std::string s = escape_control_characters(text);
  if (s.size() > max_length)
    s = s.substr(0, max_length / 2) + "..." + s.substr(s.size() - max_length / 2);
  return s;
}

class DocumentCheck {
 public:
  DocumentCheck(const std::string& path, const std::string& folder, const std::string& text)
      : path_(path), folder_(folder), text_(text) {}

  const GltfExternalFiles& files() const { return files_; }
  const std::vector<std::pair<std::string, std::uintmax_t>>& reads() const { return reads_; }
  std::size_t values() const { return values_; }

  bool null() { return scalar(); }
  bool boolean(bool) { return scalar(); }
  bool number_integer(json::number_integer_t v) {
    Number n;
    n.negative = v < 0;
    n.magnitude = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    n.text = std::to_string(v);
    return number(n);
  }
  bool number_unsigned(json::number_unsigned_t v) {
    Number n;
    n.magnitude = v;
    n.text = std::to_string(v);
    return number(n);
  }
  bool number_float(json::number_float_t v, const std::string& text) {
    Number n;
    n.negative = v < 0.0;
    n.whole = std::isfinite(v) && v == std::floor(v);
    const double magnitude = std::abs(v);
    n.magnitude = magnitude < 18446744073709551615.0 ? static_cast<std::uint64_t>(magnitude)
                                                     : ~std::uint64_t{0};
    n.text = text;
    return number(n);
  }
  bool string(std::string& v) {
    if (!scalar()) return true;
    if (is_uri_field()) check_uri(v);
    return true;
  }
  bool binary(json::binary_t&) { return scalar(); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    stack_.back().key = k;
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < position && i < text_.size(); ++i) {
      column = text_[i] == '\n' ? 1 : column + 1;
      if (text_[i] == '\n') ++line;
    }
    std::string detail = e.what();
    const std::size_t bracket = detail.find("] ");
    if (bracket != std::string::npos) detail = detail.substr(bracket + 2);
    // "parse error at line 1, column 11: syntax error ...": the place is given once, in front.
    const std::size_t place_end = detail.find(": ");
    if (detail.rfind("parse error", 0) == 0 && place_end != std::string::npos)
      detail = detail.substr(place_end + 2);
    throw std::invalid_argument(path_ + ": invalid JSON at line " + std::to_string(line) +
                                ", column " + std::to_string(column) + " (" +
                                shortened(detail, 120) + ")");
  }

 private:
  struct Level {
    bool array = false;
    std::string key;        // an object's current member
    std::size_t index = 0;  // an array's current element
    std::size_t next = 0;
  };

  // The glTF path of the value being read: `nodes[3].extensions.KHR_lights_punctual.light`.
  std::string where() const {
    std::string p;
    for (const Level& level : stack_) {
      if (level.array) {
        p += "[" + std::to_string(level.index) + "]";
      } else {
        p += (p.empty() ? "" : ".") + shortened(level.key, 60);
      }
    }
    // 256 levels of "[0]" would make a line of a thousand characters: its middle goes.
    return p.empty() ? "(the document)" : shortened(p, 160);
  }

  [[noreturn]] void fail(const std::string& value, const std::string& problem) const {
    throw std::invalid_argument(path_ + ": " + where() + ": " + value + " (" + problem + ")");
  }

  // Called as every value begins: counts it and moves its array's index.
  void begin_value() {
    if (++values_ > kMaxJsonValues) {
      fail("more than " + std::to_string(kMaxJsonValues) + " values",
           "the JSON limit a scene file has too");
    }
    if (!stack_.empty() && stack_.back().array) stack_.back().index = stack_.back().next++;
  }

  // Whether the member level `i` is at is not checked: an `extras`, or an extension this reader
  // does not know.
  bool unchecked_member(std::size_t i) const {
    const Level& level = stack_[i];
    if (level.array) return false;
    if (level.key == "extras") return true;
    return i >= 1 && !stack_[i - 1].array && stack_[i - 1].key == "extensions" &&
           level.key.rfind("KHR_", 0) != 0;
  }

  bool checking() const {
    return unchecked_from_ == kNone && !(!stack_.empty() && unchecked_member(stack_.size() - 1));
  }

  bool scalar() {
    begin_value();
    return checking();
  }

  bool open(bool array) {
    begin_value();
    if (stack_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      fail("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
           "the limit a scene file has too");
    if (unchecked_from_ == kNone && !stack_.empty() && unchecked_member(stack_.size() - 1))
      unchecked_from_ = stack_.size();
    stack_.push_back({array, {}, 0, 0});
    return true;
  }

  bool close() {
    stack_.pop_back();
    if (stack_.size() == unchecked_from_) unchecked_from_ = kNone;
    return true;
  }

  // The member a number fills: its key, or for an array's element the key holding the array.
  std::string_view field() const {
    const std::size_t n = stack_.size();
    if (n == 0) return {};
    if (!stack_[n - 1].array) return stack_[n - 1].key;
    if (n >= 2 && !stack_[n - 2].array) return stack_[n - 2].key;
    return {};
  }

  // A value of a primitive's `attributes`, or of one of its morph `targets`: an accessor index.
  bool is_attribute() const {
    const std::size_t n = stack_.size();
    if (n < 2 || stack_[n - 1].array) return false;
    if (!stack_[n - 2].array) return stack_[n - 2].key == "attributes";
    return n >= 3 && !stack_[n - 3].array && stack_[n - 3].key == "targets";
  }

  bool number(const Number& n) {
    if (!scalar()) return true;
    const std::string_view name = field();
    if (is_attribute() || is_index_field(name)) {
      if (n.negative || !n.whole || n.magnitude > kMaxIndex)
        fail(n.text, "an index is a whole number from 0 to " + std::to_string(kMaxIndex));
    } else if (is_byte_count_field(name)) {
      if (n.negative || !n.whole || n.magnitude > kMaxByteCount)
        fail(n.text, "a whole number from 0 to 2^53");
    } else if (name == "mode") {
      if (n.negative || !n.whole || n.magnitude > 6)
        fail(n.text, "a primitive's mode is 0 (points) to 6 (triangle fan)");
    } else if (name == "componentType") {
      const std::uint64_t m = n.magnitude;
      if (n.negative || !n.whole || !((m >= 5120 && m <= 5123) || m == 5125 || m == 5126))
        fail(n.text, "a component type is 5120-5123, 5125 or 5126");
    }
    return true;
  }

  bool is_uri_field() const {
    return stack_.size() == 3 && stack_[1].array && !stack_[2].array && stack_[2].key == "uri" &&
           (stack_[0].key == "buffers" || stack_[0].key == "images");
  }

  void check_uri(const std::string& uri) {
    const std::string quoted = "'" + shortened(uri, 100) + "'";
    if (uri.rfind("data:", 0) == 0) {
      if (!tinygltf::IsDataURI(uri))
        fail(shortened(uri, 60), "a data URI that is not base64 of a type glTF allows");
      return;
    }
    try {
      const std::string file = uri_file_path(uri);
      const FolderFile found = resolve_in_folder(folder_, file);
      files_[file] = found;
      reads_.emplace_back(where() + " " + quoted, found.bytes);
    } catch (const std::invalid_argument& e) {
      fail(quoted, e.what());
    }
  }

  static constexpr std::size_t kNone = ~std::size_t{0};
  const std::string& path_;
  const std::string& folder_;
  const std::string& text_;
  std::vector<Level> stack_;
  std::size_t unchecked_from_ = kNone;  // the depth from which nothing is checked
  std::size_t values_ = 0;
  GltfExternalFiles files_;
  std::vector<std::pair<std::string, std::uintmax_t>> reads_;  // every URI read, with its bytes
};

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return value;
}

}  // namespace

std::string glb_json_chunk(const std::string& bytes, const std::string& path) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) {
    throw std::invalid_argument(path + ": not a binary glTF file (" + std::to_string(bytes.size()) +
                                " bytes without the 20-byte 'glTF' header and JSON chunk)");
  }
  const std::uint32_t json_bytes = little_endian_u32(bytes, 12);
  if (little_endian_u32(bytes, 16) != 0x4E4F534Au)
    throw std::invalid_argument(path + ": binary glTF: the first chunk is not JSON");
  if (json_bytes > bytes.size() - 20) {
    throw std::invalid_argument(path + ": binary glTF: a JSON chunk of " +
                                std::to_string(json_bytes) + " bytes in a file of " +
                                std::to_string(bytes.size()));
  }
  return bytes.substr(20, json_bytes);
}

GltfExternalFiles check_gltf_document(const std::string& bytes, bool binary,
                                      const std::string& path, const std::string& folder,
                                      GltfBudget& budget) {
  budget.charge(bytes.size(), "the file itself");
  const std::string text = binary ? glb_json_chunk(bytes, path) : bytes;
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    throw std::invalid_argument(path + ": NUL byte at offset " + std::to_string(nul) +
                                (binary ? " of the JSON chunk" : "") + " (glTF JSON is text)");
  }
  DocumentCheck check(path, folder, text);
  // nlohmann's SAX parser keeps its nesting in a vector, not on the call stack.
  if (!json::sax_parse(text, &check)) throw std::invalid_argument(path + ": invalid JSON");
  budget.charge(check.values(), kGltfBytesPerJsonValue,
                "the JSON document's " + std::to_string(check.values()) + " values");
  for (const auto& [what, file_bytes] : check.reads()) budget.charge(file_bytes, what);
  return check.files();
}

}  // namespace scenes
