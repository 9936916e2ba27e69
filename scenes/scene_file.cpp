#include "scenes/scene_file.h"

#include "scenes/gltf_scene.h"

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenes/gltf_budget.h"
#include "scenes/scene_folder.h"
#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

using json = nlohmann::json;

// RFC 6901 escaping of one path segment.
std::string pointer_segment(const std::string& key) {
  std::string s;
  for (char c : key) {
    if (c == '~') {
      s += "~0";
    } else if (c == '/') {
      s += "~1";
    } else {
      s += c;
    }
  }
  return s;
}

// Control characters would break the one-line message (or drive the terminal): escaped, then
// shortened in the middle.
std::string one_line(const std::string& raw, std::size_t max_length) {
  std::string s = escape_control_characters(raw);
  if (s.size() > max_length)
    s = s.substr(0, max_length / 2) + "..." + s.substr(s.size() - max_length / 2);
  return s;
}

std::string value_text(const json& v) {
  return one_line(v.dump(), 60);
}

[[noreturn]] void fail(const std::string& source, const std::string& path,
                       const std::string& problem) {
  throw std::invalid_argument(source + ": " + one_line(path.empty() ? "/" : path, 160) + ": " +
                              problem);
}

// Builds the JSON document through nlohmann's (iterative) SAX parser, refusing nesting deeper
// than kMaxJsonDepth and duplicate keys, and naming the JSON path of every syntax error.
class DomBuilder {
 public:
  DomBuilder(const std::string& source, const std::string& text, json& root)
      : source_(source), text_(text), root_(root) {}

  // JSON path -> the number as typed, for the numbers a float rounds.
  const std::map<std::string, std::string>& typed_numbers() const { return typed_numbers_; }

  bool null() { return add(nullptr); }
  bool boolean(bool v) { return add(v); }
  bool number_integer(json::number_integer_t v) { return add(v); }
  bool number_unsigned(json::number_unsigned_t v) { return add(v); }
  bool number_float(json::number_float_t v, const std::string& text) {
    // A number the 32-bit float does not hold exactly keeps its text, so that a message about
    // its value repeats what was typed (180.00001, not the float's 180).
    if (static_cast<double>(static_cast<float>(v)) != v) typed_numbers_[path()] = text;
    return add(v);
  }
  bool string(std::string& v) { return add(std::move(v)); }
  bool binary(json::binary_t& v) { return add(std::move(v)); }
  bool start_object(std::size_t /*elements*/) { return open(json::object()); }
  bool start_array(std::size_t /*elements*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    keys_.back() = k;
    if (stack_.back()->contains(k)) fail(source_, path(), "duplicate key");
    return true;
  }
  bool parse_error(std::size_t position, const std::string& /*last_token*/,
                   const nlohmann::detail::exception& e) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < position && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string detail = e.what();
    const std::size_t bracket = detail.find("] ");
    if (bracket != std::string::npos) detail = detail.substr(bracket + 2);
    fail(source_, path(),
         "invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(column) +
             " (" + one_line(detail, 120) + ")");
  }

 private:
  // The path of the value being read: each open container's current child.
  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const json& c = *stack_[i];
      if (c.is_array()) {
        const std::size_t index = i + 1 == stack_.size() ? c.size() : c.size() - 1;
        p += "/" + std::to_string(index);
      } else {
        p += "/" + pointer_segment(keys_[i]);
      }
    }
    return p;
  }

  json* place(json&& v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    json& slot = top[keys_.back()];
    slot = std::move(v);
    return &slot;
  }

  // Counted before the value exists, so a file of many small values stops near the budget.
  void count_value() {
    if (++values_ > kMaxJsonValues) {
      fail(source_, path(),
           "more than " + std::to_string(kMaxJsonValues) + " JSON values in the file");
    }
  }

  bool add(json&& v) {
    count_value();
    place(std::move(v));
    return true;
  }

  bool open(json&& container) {
    count_value();
    if (stack_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      fail(source_, path(), "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    stack_.push_back(place(std::move(container)));
    keys_.emplace_back();
    return true;
  }

  bool close() {
    stack_.pop_back();
    keys_.pop_back();
    return true;
  }

  const std::string& source_;
  const std::string& text_;
  json& root_;
  std::vector<json*> stack_;
  std::vector<std::string> keys_;
  std::size_t values_ = 0;
  std::map<std::string, std::string> typed_numbers_;
};

// validate_description reports "/json/path: problem (value)" with the value it checked, a float;
// where the file's text for that path was rounded to get it, the text replaces the float.
std::string with_typed_value(const std::string& message,
                             const std::map<std::string, std::string>& typed_numbers) {
  const std::size_t path_end = message.find(": ");
  const std::size_t value_start = message.rfind(" (");
  if (path_end == std::string::npos || value_start == std::string::npos || message.back() != ')')
    return message;
  const auto typed = typed_numbers.find(message.substr(0, path_end));
  if (typed == typed_numbers.end()) return message;
  return message.substr(0, value_start) + " (" + typed->second + ")";
}

// Turns the JSON document into a description, checking keys and types; values are checked by
// validate_description afterwards, with the same paths.
class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  SceneDescription read(const json& doc) {
    SceneDescription scene;
    expect_object(doc, "");
    check_keys(doc, "",
               {"levrt_scene", "name", "level", "camera", "ambient", "background", "materials",
                "masters", "root"});
    const json& version = require(doc, "", "levrt_scene");
    if (!version.is_number_integer() || version.get<std::int64_t>() != kSceneFileVersion) {
      fail(source_, "/levrt_scene",
           "must be " + std::to_string(kSceneFileVersion) + " (" + value_text(version) + ")");
    }
    if (doc.contains("name")) scene.name = read_string(doc["name"], "/name");
    if (doc.contains("level")) scene.level = read_int(doc["level"], "/level");
    read_camera(require(doc, "", "camera"), scene.camera);
    if (doc.contains("ambient")) scene.ambient = read_vec3(doc["ambient"], "/ambient");
    if (doc.contains("background")) scene.background = read_vec3(doc["background"], "/background");
    if (doc.contains("materials")) {
      const json& list = doc["materials"];
      expect_array(list, "/materials");
      if (list.size() > kMaxMaterials) {
        fail(source_, "/materials", "more than " + std::to_string(kMaxMaterials) + " materials");
      }
      for (std::size_t i = 0; i < list.size(); ++i) {
        read_material(list[i], "/materials/" + std::to_string(i), scene);
      }
    }
    if (doc.contains("masters")) {
      const json& list = doc["masters"];
      expect_array(list, "/masters");
      if (list.size() > kMaxMasters)
        fail(source_, "/masters", "more than " + std::to_string(kMaxMasters) + " masters");
      // Names first, so that masters may instance masters defined later in the file.
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/masters/" + std::to_string(i);
        expect_object(list[i], path);
        check_keys(list[i], path, {"name", "node"});
        const std::string name = read_string(require(list[i], path, "name"), path + "/name");
        if (!master_index_.emplace(name, static_cast<std::uint32_t>(i)).second) {
          fail(source_, path + "/name",
               "a master of this name is already defined ('" + one_line(name, 60) + "')");
        }
        scene.masters.push_back({name, SceneNode{}});
      }
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string path = "/masters/" + std::to_string(i);
        scene.masters[i].node = read_node(require(list[i], path, "node"), path + "/node");
      }
    }
    scene.root = read_node(require(doc, "", "root"), "/root");
    return scene;
  }

 private:
  void expect_object(const json& v, const std::string& path) const {
    if (!v.is_object()) fail(source_, path, "must be an object (" + value_text(v) + ")");
  }
  void expect_array(const json& v, const std::string& path) const {
    if (!v.is_array()) fail(source_, path, "must be an array (" + value_text(v) + ")");
  }

  void check_keys(const json& object, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
    for (const auto& item : object.items()) {
      bool known = false;
      for (const char* k : allowed) known = known || item.key() == k;
      if (!known) {
        std::string list;
        for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(source_, path + "/" + pointer_segment(item.key()),
             "unknown key (expected one of: " + list + ")");
      }
    }
  }

  const json& require(const json& object, const std::string& path, const char* key) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(source_, path + "/" + key, "missing");
    return *it;
  }

  float read_float(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(source_, path, "must be a number (" + value_text(v) + ")");
    const double d = v.get<double>();
    if (std::abs(d) > static_cast<double>(std::numeric_limits<float>::max())) {
      fail(source_, path, "must be finite as a 32-bit float (" + value_text(v) + ")");
    }
    return static_cast<float>(d);
  }

  int read_int(const json& v, const std::string& path) const {
    if (!v.is_number_integer()) fail(source_, path, "must be an integer (" + value_text(v) + ")");
    if (v.is_number_unsigned()
            ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<int>::max())
            : (v.get<std::int64_t>() > std::numeric_limits<int>::max() ||
               v.get<std::int64_t>() < std::numeric_limits<int>::min())) {
      fail(source_, path, "integer out of range (" + value_text(v) + ")");
    }
    return static_cast<int>(v.get<std::int64_t>());
  }

  std::string read_string(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(source_, path, "must be a string (" + value_text(v) + ")");
    return v.get<std::string>();
  }

  glm::vec3 read_vec3(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3)
      fail(source_, path, "must be an array of 3 numbers (" + value_text(v) + ")");
    return {read_float(v[0], path + "/0"), read_float(v[1], path + "/1"),
            read_float(v[2], path + "/2")};
  }

  void read_camera(const json& v, renderer::Camera& camera) const {
    expect_object(v, "/camera");
    check_keys(v, "/camera",
               {"position", "target", "up", "fov_degrees", "orthographic_half_height"});
    camera.position = read_vec3(require(v, "/camera", "position"), "/camera/position");
    camera.target = read_vec3(require(v, "/camera", "target"), "/camera/target");
    if (v.contains("up")) camera.up = read_vec3(v["up"], "/camera/up");
    if (v.contains("fov_degrees"))
      camera.vertical_fov_deg = read_float(v["fov_degrees"], "/camera/fov_degrees");
    if (v.contains("orthographic_half_height")) {
      camera.orthographic_half_height =
          read_float(v["orthographic_half_height"], "/camera/orthographic_half_height");
    }
  }

  void read_material(const json& v, const std::string& path, SceneDescription& scene) {
    expect_object(v, path);
    check_keys(v, path, {"name", "colour", "ka", "kd", "ks", "shininess", "kr", "kt", "ior"});
    NamedMaterial m;
    m.name = read_string(require(v, path, "name"), path + "/name");
    if (!material_index_.emplace(m.name, static_cast<std::uint32_t>(scene.materials.size()))
             .second) {
      fail(source_, path + "/name",
           "a material of this name is already defined ('" + one_line(m.name, 60) + "')");
    }
    if (v.contains("colour")) m.material.colour = read_vec3(v["colour"], path + "/colour");
    const std::pair<const char*, float renderer::Material::*> scalars[] = {
        {"ka", &renderer::Material::ka},  {"kd", &renderer::Material::kd},
        {"ks", &renderer::Material::ks},  {"shininess", &renderer::Material::shininess},
        {"kr", &renderer::Material::kr},  {"kt", &renderer::Material::kt},
        {"ior", &renderer::Material::ior}};
    for (const auto& [key, field] : scalars) {
      if (v.contains(key)) m.material.*field = read_float(v[key], path + "/" + key);
    }
    scene.materials.push_back(std::move(m));
  }

  std::uint32_t read_material_ref(const json& node, const std::string& path) const {
    const std::string name = read_string(require(node, path, "material"), path + "/material");
    const auto it = material_index_.find(name);
    if (it == material_index_.end())
      fail(source_, path + "/material", "no material named '" + one_line(name, 60) + "'");
    return it->second;
  }

  // Recursion depth is bounded by kMaxJsonDepth (the document is already parsed).
  SceneNode read_node(const json& v, const std::string& path) {
    expect_object(v, path);
    if (++node_count_ > kMaxSceneNodes)
      fail(source_, path, "more than " + std::to_string(kMaxSceneNodes) + " nodes");
    const std::string type = read_string(require(v, path, "type"), path + "/type");
    SceneNode node;
    if (type == "affine") {
      check_keys(v, path, {"type", "translate", "rotate", "scale", "child"});
      Affine a;
      if (v.contains("translate")) a.translate = read_vec3(v["translate"], path + "/translate");
      if (v.contains("rotate")) {
        const json& r = v["rotate"];
        const std::string rp = path + "/rotate";
        expect_object(r, rp);
        check_keys(r, rp, {"axis", "degrees"});
        a.rotate_axis = read_vec3(require(r, rp, "axis"), rp + "/axis");
        a.rotate_degrees = read_float(require(r, rp, "degrees"), rp + "/degrees");
      }
      if (v.contains("scale")) a.scale = read_float(v["scale"], path + "/scale");
      node.data = a;
      node.children.push_back(read_node(require(v, path, "child"), path + "/child"));
    } else if (type == "union") {
      check_keys(v, path, {"type", "children"});
      const json& list = require(v, path, "children");
      expect_array(list, path + "/children");
      node.children.reserve(list.size());
      for (std::size_t k = 0; k < list.size(); ++k) {
        node.children.push_back(read_node(list[k], path + "/children/" + std::to_string(k)));
      }
    } else if (type == "instance") {
      check_keys(v, path, {"type", "master"});
      const std::string name = read_string(require(v, path, "master"), path + "/master");
      const auto it = master_index_.find(name);
      if (it == master_index_.end())
        fail(source_, path + "/master", "no master named '" + one_line(name, 60) + "'");
      node.data = Instance{it->second};
    } else if (type == "sphere") {
      check_keys(v, path, {"type", "material", "centre", "radius"});
      node.data = SphereShape{read_material_ref(v, path),
                              read_vec3(require(v, path, "centre"), path + "/centre"),
                              read_float(require(v, path, "radius"), path + "/radius")};
    } else if (type == "box") {
      check_keys(v, path, {"type", "material", "lo", "hi"});
      node.data =
          BoxShape{read_material_ref(v, path), read_vec3(require(v, path, "lo"), path + "/lo"),
                   read_vec3(require(v, path, "hi"), path + "/hi")};
    } else if (type == "cylinder") {
      check_keys(v, path, {"type", "material", "a", "b", "radius", "segments"});
      CylinderShape c;
      c.material = read_material_ref(v, path);
      c.a = read_vec3(require(v, path, "a"), path + "/a");
      c.b = read_vec3(require(v, path, "b"), path + "/b");
      c.radius = read_float(require(v, path, "radius"), path + "/radius");
      if (v.contains("segments")) c.segments = read_int(v["segments"], path + "/segments");
      node.data = c;
    } else if (type == "quad") {
      check_keys(v, path, {"type", "material", "corner", "edge_u", "edge_v"});
      node.data = QuadShape{read_material_ref(v, path),
                            read_vec3(require(v, path, "corner"), path + "/corner"),
                            read_vec3(require(v, path, "edge_u"), path + "/edge_u"),
                            read_vec3(require(v, path, "edge_v"), path + "/edge_v")};
    } else if (type == "point_light") {
      check_keys(v, path, {"type", "intensity", "range"});
      PointLightSource p;
      p.intensity = read_vec3(require(v, path, "intensity"), path + "/intensity");
      if (v.contains("range")) p.range = read_float(v["range"], path + "/range");
      node.data = p;
    } else if (type == "spot_light") {
      check_keys(v, path,
                 {"type", "intensity", "cone_degrees", "dropoff", "range", "inner_cone_degrees"});
      SpotLightSource s;
      s.intensity = read_vec3(require(v, path, "intensity"), path + "/intensity");
      s.cone_degrees = read_float(require(v, path, "cone_degrees"), path + "/cone_degrees");
      if (v.contains("dropoff")) s.dropoff = read_float(v["dropoff"], path + "/dropoff");
      if (v.contains("range")) s.range = read_float(v["range"], path + "/range");
      if (v.contains("inner_cone_degrees")) {
        s.inner_cone_degrees = read_float(v["inner_cone_degrees"], path + "/inner_cone_degrees");
        if (s.inner_cone_degrees < 0.0f) {
          fail(source_, path + "/inner_cone_degrees",
               "must be >= 0 (" + value_text(v["inner_cone_degrees"]) + ")");
        }
      }
      node.data = s;
    } else {
      fail(source_, path + "/type",
           "unknown node type (expected one of: affine, union, instance, sphere, box, cylinder, "
           "quad, "
           "point_light, spot_light) (" +
               value_text(v["type"]) + ")");
    }
    return node;
  }

  const std::string& source_;
  std::map<std::string, std::uint32_t> master_index_;
  std::map<std::string, std::uint32_t> material_index_;
  std::size_t node_count_ = 0;
};

}  // namespace

namespace {

// The code points a message shows as a \u escape (\u202e: four hex digits) though they are valid
// text: the C1 controls (a terminal may take U+009B as CSI) and the invisible format characters
// that reorder or hide what follows (the bidirectional embeddings, overrides and isolates, the
// marks, zero-width characters, the line and paragraph separators, the byte order mark).
bool is_escaped_code_point(std::uint32_t cp) {
  return (cp >= 0x80 && cp <= 0x9f) || cp == 0x061c || (cp >= 0x200b && cp <= 0x200f) ||
         (cp >= 0x2028 && cp <= 0x202e) || cp == 0x2060 || (cp >= 0x2066 && cp <= 0x2069) ||
         cp == 0xfeff;
}

// The length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong form, no
// surrogate, nothing past U+10FFFF) and its code point; 0 when none starts there.
std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& cp) {
  const auto byte = [&text](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf;  // the second byte's range
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
    cp = lead & 0x1fu;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    cp = lead & 0x0fu;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    cp = lead & 0x07u;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    const unsigned char c = byte(i + k);
    if (k == 1 ? (c < low || c > high) : (c < 0x80 || c > 0xbf)) return 0;
    cp = (cp << 6) | (c & 0x3fu);
  }
  return length;
}

}  // namespace

std::string escape_control_characters(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const unsigned char byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (byte < 0x20 || byte == 0x7f) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else if (byte < 0x80) {
      out += c;
    } else {
      std::uint32_t cp = 0;
      const std::size_t length = utf8_sequence(text, i, cp);
      if (length == 0) {  // a byte of no UTF-8 character: shown as itself, \xNN
        out += "\\x";
        out += kHex[byte >> 4];
        out += kHex[byte & 0xf];
      } else if (is_escaped_code_point(cp)) {
        out += "\\u";
        for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(cp >> shift) & 0xf];
        i += length;
        continue;
      } else {
        out.append(text.substr(i, length));
        i += length;
        continue;
      }
    }
    ++i;
  }
  return out;
}

bool is_scene_file_name(std::string_view name) {
  constexpr std::string_view kSuffix = ".json";
  return (name.size() > kSuffix.size() && name.substr(name.size() - kSuffix.size()) == kSuffix) ||
         is_gltf_file_name(name);
}

SceneDescription parse_scene_json(const std::string& text, const std::string& source) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos) {
    throw std::invalid_argument(source + ": NUL byte at offset " + std::to_string(nul) +
                                " (a scene file is text)");
  }
  json doc;
  DomBuilder builder(source, text, doc);
  if (!json::sax_parse(text, &builder)) fail(source, "", "invalid JSON");
  SceneDescription scene = Reader(source).read(doc);
  try {
    validate_description(scene);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(
        source + ": " +
        escape_control_characters(with_typed_value(e.what(), builder.typed_numbers())));
  }
  return scene;
}

SceneDescription load_scene_file(const std::string& path, const SceneFileOptions& options) {
  namespace fs = std::filesystem;
  std::string text;
  // A binary glTF carries its buffers: it may be as large as the glTF budget, which charges it
  // (gltf_budget.h); JSON text, a scene file's or a glTF's, stays within kMaxSceneFileBytes.
  const bool gltf = is_gltf_file_name(path);
  const bool binary_gltf = gltf && regular_file_starts_with(path, "glTF");
  read_regular_file(path, binary_gltf ? kMaxGltfSceneBytes : kMaxSceneFileBytes, "scene file",
                    text);
  if (gltf) return parse_gltf_scene(text, path, options.camera);
  if (options.camera != 0) {
    throw std::invalid_argument(path + ": camera: " + std::to_string(options.camera) +
                                " (a scene file has one camera, 0)");
  }
  SceneDescription scene = parse_scene_json(text, path);
  if (scene.name.empty()) scene.name = fs::path(path).stem().string();
  return scene;
}

}  // namespace scenes
