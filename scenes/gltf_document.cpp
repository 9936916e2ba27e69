#include "scenes/gltf_document.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "scenes/gltf_schema.h"
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
  double value = 0.0;
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
  const std::vector<std::string>& ignored_extensions() const { return ignored_extensions_; }
  const std::vector<std::pair<std::string, std::uintmax_t>>& reads() const { return reads_; }
  std::size_t values() const { return values_; }

  bool null() { return scalar({GltfJsonKind::null, 0.0, "null"}); }
  bool boolean(bool v) { return scalar({GltfJsonKind::boolean, 0.0, v ? "true" : "false"}); }
  bool number_integer(json::number_integer_t v) {
    Number n;
    n.negative = v < 0;
    n.value = static_cast<double>(v);
    n.magnitude = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    n.text = std::to_string(v);
    return number(n);
  }
  bool number_unsigned(json::number_unsigned_t v) {
    Number n;
    n.magnitude = v;
    n.value = static_cast<double>(v);
    n.text = std::to_string(v);
    return number(n);
  }
  bool number_float(json::number_float_t v, const std::string& text) {
    Number n;
    n.negative = v < 0.0;
    n.value = v;
    n.whole = std::isfinite(v) && v == std::floor(v);
    const double magnitude = std::abs(v);
    n.magnitude = magnitude < 18446744073709551615.0 ? static_cast<std::uint64_t>(magnitude)
                                                     : ~std::uint64_t{0};
    n.text = text;
    return number(n);
  }
  bool string(std::string& v) {
    if (!scalar({GltfJsonKind::string, 0.0, v})) return true;
    if (is_uri_field()) check_uri(v);
    return true;
  }
  bool binary(json::binary_t&) { return scalar({GltfJsonKind::null, 0.0, "binary"}); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    Level& level = stack_.back();
    level.key = k;
    if (is_camera_object(level)) level.camera_members.emplace_back(k, std::string());
    if (level.pattern == "nodes[]") {
      if (k == "matrix") level.node_transform |= kNodeMatrix;
      if (k == "translation" || k == "rotation" || k == "scale") level.node_transform |= kNodeTrs;
    }
    for (std::size_t i = 0; i < level.missing.size(); ++i) {
      if (level.missing[i] == k) level.missing.erase(level.missing.begin() + static_cast<long>(i));
    }
    return true;
  }

  // Every index the document holds points into its array (counted as the arrays closed), and
  // every extension required is used too (the spec: extensionsRequired is a subset).
  void check_references() const {
    // A buffer's data URI decodes to its byteLength exactly (tinygltf refuses anything else, with
    // a message that quotes the whole URI and no reason).
    for (const auto& [index, buffer] : buffers_) {
      if (buffer.data_bytes && buffer.byte_length && *buffer.data_bytes != *buffer.byte_length) {
        fail_at("buffers[" + std::to_string(index) + "].uri",
                "data of " + std::to_string(*buffer.data_bytes) + " bytes",
                "its byteLength is " + std::to_string(*buffer.byte_length));
      }
    }
    for (const auto& [where, name] : required_extensions_) {
      if (std::find(used_extensions_.begin(), used_extensions_.end(), name) ==
          used_extensions_.end())
        fail_at(where, "'" + shortened(name, 100) + "'", "required but not in extensionsUsed");
    }
    for (const Reference& reference : references_) {
      const auto found = lengths_.find(reference.target);
      const std::size_t length = found == lengths_.end() ? 0 : found->second;
      if (reference.value >= length) {
        fail_at(reference.where, std::to_string(reference.value),
                "an index past the " + std::to_string(length) + " element(s) of " +
                    std::string(reference.target));
      }
    }
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
    std::string pattern;                    // gltf_schema.h: the path with every index written []
    const GltfFieldRule* rule = nullptr;    // the container's own rule, if levrt reads it
    std::vector<std::string_view> missing;  // required members not met yet
    // A camera's or light's members (and the text of scalar ones), for the checks between
    // members.
    std::vector<std::pair<std::string, std::string>> camera_members;
    unsigned node_transform = 0;  // a node's kNodeMatrix and kNodeTrs members met
  };
  static constexpr unsigned kNodeMatrix = 1, kNodeTrs = 2;

  // An index field, checked against its array's length once the whole document is read.
  struct Reference {
    std::string where;
    std::uint64_t value = 0;
    std::string_view target;
  };

  // The glTF path of the value being read: `nodes[3].extensions.KHR_lights_punctual.light`.
  std::string where() const { return where_of(stack_.size()); }

  // The glTF path of the value the first `depth` levels lead to.
  std::string where_of(std::size_t depth) const {
    std::string p;
    for (std::size_t i = 0; i < depth; ++i) {
      const Level& level = stack_[i];
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
    fail_at(where(), value, problem);
  }

  [[noreturn]] void fail_at(const std::string& where, const std::string& value,
                            const std::string& problem) const {
    throw std::invalid_argument(path_ + ": " + where + ": " + value + " (" + problem + ")");
  }

  // The schema's rule for the value beginning (gltf_schema.h), or nullptr: outside the checked
  // part of the document, or a field levrt does not read.
  const GltfFieldRule* rule_here() const {
    if (stack_.empty() || unchecked_from_ != kNone || unchecked_member(stack_.size() - 1))
      return nullptr;
    const Level& level = stack_.back();
    return find_gltf_field_rule(level.pattern, level.key, level.array);
  }

  // Checks the value beginning against its rule; an index is kept for check_references and an
  // extension used but not honoured for the warning.
  const GltfFieldRule* check_rule(const GltfJsonValue& value) {
    const GltfFieldRule* rule = rule_here();
    if (stack_.empty() && value.kind != GltfJsonKind::object)
      fail(std::string(value.text), "a glTF document is a JSON object");
    if (!rule) return nullptr;
    const std::string problem = gltf_field_problem(*rule, value);
    if (!problem.empty()) {
      const std::string shown = value.kind == GltfJsonKind::string
                                    ? "'" + shortened(std::string(value.text), 100) + "'"
                                    : shortened(std::string(value.text), 100);
      fail(shown, problem);
    }
    if (!rule->indexes.empty())
      references_.push_back({where(), static_cast<std::uint64_t>(value.number), rule->indexes});
    if (rule->special == GltfSpecialCheck::used_extension) {
      // glTF lists each extension once (uniqueItems).
      if (std::find(used_extensions_.begin(), used_extensions_.end(), value.text) !=
          used_extensions_.end())
        fail("'" + shortened(std::string(value.text), 100) + "'", "listed twice in extensionsUsed");
      used_extensions_.emplace_back(value.text);
      if (!is_honoured_gltf_extension(value.text)) ignored_extensions_.emplace_back(value.text);
    }
    if (rule->special == GltfSpecialCheck::required_extension) {
      for (const auto& [earlier_where, name] : required_extensions_) {
        if (name == value.text)
          fail("'" + shortened(name, 100) + "'", "listed twice in extensionsRequired");
      }
      required_extensions_.emplace_back(where(), value.text);
    }
    return rule;
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

  bool scalar(const GltfJsonValue& value) {
    begin_value();
    check_rule(value);
    if (!stack_.empty() && is_camera_object(stack_.back()))
      stack_.back().camera_members.back().second = std::string(value.text);
    return checking();
  }

  bool open(bool array) {
    begin_value();
    if (stack_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      fail("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
           "the limit a scene file has too");
    const GltfJsonKind kind = array ? GltfJsonKind::array : GltfJsonKind::object;
    Level level{array, {}, 0, 0, {}, nullptr, {}, {}, 0};
    level.rule = check_rule({kind, 0.0, array ? "an array" : "an object"});
    if (unchecked_from_ == kNone && !stack_.empty() && unchecked_member(stack_.size() - 1))
      unchecked_from_ = stack_.size();
    if (unchecked_from_ == kNone) {
      if (!stack_.empty()) {
        const Level& parent = stack_.back();
        level.pattern = gltf_member_pattern(parent.pattern, parent.key, parent.array);
      }
      if (!array) level.missing = required_gltf_members(level.pattern);
    }
    stack_.push_back(std::move(level));
    return true;
  }

  static bool is_camera_object(const Level& level) {
    return !level.array &&
           (level.pattern == "cameras[]" || level.pattern == "cameras[].orthographic" ||
            level.pattern == "extensions.KHR_lights_punctual.lights[]");
  }

  static const std::string* camera_member(const Level& level, std::string_view name) {
    for (const auto& [key, text] : level.camera_members) {
      if (key == name) return &text;
    }
    return nullptr;
  }

  // What the schema says between a camera's members: the object its type names is there, and an
  // orthographic zfar lies beyond znear.
  void check_camera(const Level& level) const {
    const std::string where = where_of(stack_.size() - 1);
    // The extension: a spot light has its `spot` object (tinygltf's refusal named no light).
    if (level.pattern == "extensions.KHR_lights_punctual.lights[]") {
      const std::string* type = camera_member(level, "type");
      if (type && *type == "spot" && !camera_member(level, "spot"))
        fail_at(where + ".spot", "missing", "a member a light of type spot requires");
      return;
    }
    if (level.pattern == "cameras[]") {
      const std::string* type = camera_member(level, "type");
      if (type && (*type == "perspective" || *type == "orthographic") &&
          !camera_member(level, *type))
        fail_at(where + "." + *type, "missing", "a member a camera of type " + *type + " requires");
      return;
    }
    const std::string* znear = camera_member(level, "znear");
    const std::string* zfar = camera_member(level, "zfar");
    if (znear && zfar &&
        !(std::strtod(zfar->c_str(), nullptr) > std::strtod(znear->c_str(), nullptr)))
      fail_at(where + ".zfar", *zfar, "beyond znear " + *znear + " is expected");
  }

  bool close() {
    const Level& level = stack_.back();
    if (is_camera_object(level)) check_camera(level);
    // glTF: a node has a matrix or TRS properties, not both (tinygltf reads the matrix alone).
    if (level.node_transform == (kNodeMatrix | kNodeTrs)) {
      fail_at(where_of(stack_.size() - 1) + ".matrix", "given with translation, rotation or scale",
              "a node has a matrix or those, not both");
    }
    if (!level.missing.empty()) {
      fail_at(where_of(stack_.size() - 1) + "." + std::string(level.missing.front()), "missing",
              "a member glTF requires");
    }
    if (level.rule && level.next < level.rule->min_length) {
      fail_at(where_of(stack_.size() - 1), "an empty array",
              "glTF asks for at least " + std::to_string(level.rule->min_length) +
                  " element(s) or no member");
    }
    if (level.rule && level.rule->length != 0 && level.next != level.rule->length) {
      fail_at(where_of(stack_.size() - 1), std::to_string(level.next) + " values",
              std::to_string(level.rule->length) + " are expected");
    }
    if (level.array && is_gltf_index_target(level.pattern)) lengths_[level.pattern] = level.next;
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
    const GltfJsonKind kind = n.whole ? GltfJsonKind::integer : GltfJsonKind::number;
    if (!scalar({kind, n.value, n.text})) return true;
    const std::string_view name = field();
    if (is_attribute() || is_index_field(name)) {
      if (n.negative || !n.whole || n.magnitude > kMaxIndex)
        fail(n.text, "an index is a whole number from 0 to " + std::to_string(kMaxIndex));
    } else if (is_byte_count_field(name)) {
      if (n.negative || !n.whole || n.magnitude > kMaxByteCount)
        fail(n.text, "a whole number from 0 to 2^53");
      if (name == "byteLength" && stack_.size() == 3 && stack_[0].key == "buffers" &&
          stack_[1].array && !stack_[2].array) {
        buffers_[stack_[1].index].byte_length = n.magnitude;
      }
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

  // The bytes a data URI's base64 decodes to. Refuses a character outside the alphabet (tinygltf's
  // decoder stops there without a word, and its message then quotes the whole URI), data that
  // ends in a lone character (no byte count gives it), and no data at all.
  std::uint64_t data_uri_bytes(const std::string& uri) const {
    const std::string_view data = std::string_view(uri).substr(uri.find(',') + 1);
    std::size_t end = data.size();
    while (end > 0 && data[end - 1] == '=' && data.size() - end < 2) --end;  // the padding
    const auto is_base64 = [](unsigned char c) { return std::isalnum(c) || c == '+' || c == '/'; };
    for (std::size_t i = 0; i < end; ++i) {
      if (!is_base64(static_cast<unsigned char>(data[i]))) {
        fail(shortened(uri, 60), "not base64: character " + std::to_string(i + 1) +
                                     " of its data is '" + shortened(std::string(1, data[i]), 8) +
                                     "'");
      }
    }
    if (end == 0) fail(shortened(uri, 60), "a data URI without data");
    if (end % 4 == 1) {
      fail(shortened(uri, 60), "not base64: " + std::to_string(end) +
                                   " characters of data, one too many for whole bytes");
    }
    return end / 4 * 3 + (end % 4 == 0 ? 0 : end % 4 - 1);
  }

  void check_uri(const std::string& uri) {
    const std::string quoted = "'" + shortened(uri, 100) + "'";
    if (uri.rfind("data:", 0) == 0) {
      if (!tinygltf::IsDataURI(uri))
        fail(shortened(uri, 60), "a data URI that is not base64 of a type glTF allows");
      const std::uint64_t bytes = data_uri_bytes(uri);
      if (stack_[0].key == "buffers") buffers_[stack_[1].index].data_bytes = bytes;
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
  std::vector<Reference> references_;
  std::map<std::string, std::size_t, std::less<>> lengths_;  // index targets by pattern
  std::vector<std::string> ignored_extensions_;
  std::vector<std::string> used_extensions_;
  std::vector<std::pair<std::string, std::string>> required_extensions_;  // where, name
  std::vector<std::pair<std::string, std::uintmax_t>> reads_;  // every URI read, with its bytes
  // Each buffer's byteLength and what its data URI decodes to, as they are read.
  struct BufferSizes {
    std::optional<std::uint64_t> byte_length, data_bytes;
  };
  std::map<std::size_t, BufferSizes> buffers_;
};

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return value;
}

}  // namespace

bool is_glb(const std::string& bytes) {
  return bytes.compare(0, 4, "glTF") == 0;
}

std::string glb_json_chunk(const std::string& bytes, const std::string& path) {
  if (bytes.size() < 20 || !is_glb(bytes)) {
    throw std::invalid_argument(path + ": not a binary glTF file (" + std::to_string(bytes.size()) +
                                " bytes without the 20-byte 'glTF' header and JSON chunk)");
  }
  const std::uint32_t version = little_endian_u32(bytes, 4);
  if (version != 2) {
    throw std::invalid_argument(path + ": binary glTF: header version " + std::to_string(version) +
                                " (levrt reads version 2)");
  }
  const std::uint32_t length_bytes = little_endian_u32(bytes, 8);
  if (length_bytes != bytes.size()) {
    throw std::invalid_argument(path + ": binary glTF: header length " +
                                std::to_string(length_bytes) + " bytes, the file has " +
                                std::to_string(bytes.size()));
  }
  const std::uint32_t json_bytes = little_endian_u32(bytes, 12);
  if (little_endian_u32(bytes, 16) != 0x4E4F534Au)
    throw std::invalid_argument(path + ": binary glTF: the first chunk is not JSON");
  if (json_bytes > bytes.size() - 20) {
    throw std::invalid_argument(path + ": binary glTF: a JSON chunk of " +
                                std::to_string(json_bytes) + " bytes in a file of " +
                                std::to_string(bytes.size()));
  }
  // The JSON is held as a .gltf's or a scene file's is (and listed for the inputs whole).
  if (json_bytes > kMaxSceneFileBytes) {
    throw std::invalid_argument(path + ": binary glTF: a JSON chunk of " +
                                std::to_string(json_bytes) + " bytes, more than the " +
                                byte_limit_text(kMaxSceneFileBytes) + " a glTF's JSON may have");
  }
  return bytes.substr(20, json_bytes);
}

GltfDocumentFacts check_gltf_document(const std::string& bytes, bool binary,
                                      const std::string& path, const std::string& folder,
                                      GltfBudget& budget) {
  budget.charge(bytes.size(), "the file itself");
  const std::string text = binary ? glb_json_chunk(bytes, path) : bytes;
  // nlohmann's parser skips a byte order mark (and so would read the file); glTF forbids one.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) {
    throw std::invalid_argument(path + ": a byte order mark before the JSON" +
                                (binary ? " chunk" : std::string()) +
                                " (glTF's JSON is UTF-8 without one)");
  }
  // tinygltf copies a binary file's BIN chunk into its buffer while the file is still held.
  if (binary) budget.charge(bytes.size() - 20 - text.size(), "the binary chunk as its buffer");
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    throw std::invalid_argument(path + ": NUL byte at offset " + std::to_string(nul) +
                                (binary ? " of the JSON chunk" : "") + " (glTF JSON is text)");
  }
  DocumentCheck check(path, folder, text);
  // nlohmann's SAX parser keeps its nesting in a vector, not on the call stack.
  if (!json::sax_parse(text, &check)) throw std::invalid_argument(path + ": invalid JSON");
  check.check_references();
  budget.charge(check.values(), kGltfBytesPerJsonValue,
                "the JSON document's " + std::to_string(check.values()) + " values");
  for (const auto& [what, file_bytes] : check.reads()) budget.charge(file_bytes, what);
  return {check.files(), check.ignored_extensions()};
}

}  // namespace scenes
