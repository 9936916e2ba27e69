#include "scenes/gltf_schema.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

namespace scenes {
namespace {

using Kind = GltfJsonKind;

constexpr double kHalfPi = 1.57079632679489661923;

// The extensions levrt honours (gltf_scene.cpp and gltf_materials.cpp read the first five;
// gltf_meshes.cpp takes the byte and short vertex attributes of KHR_mesh_quantization when it is
// listed, and refuses them otherwise).
constexpr std::string_view kHonouredExtensions[] = {
    "KHR_lights_punctual", "KHR_materials_transmission",
    "KHR_materials_ior",   "KHR_materials_emissive_strength",
    "KHR_materials_unlit", "KHR_mesh_quantization"};

GltfFieldRule field(std::string_view pattern, Kind kind) {
  GltfFieldRule rule;
  rule.pattern = pattern;
  rule.kind = kind;
  return rule;
}
GltfFieldRule object(std::string_view pattern) {
  return field(pattern, Kind::object);
}
GltfFieldRule array(std::string_view pattern, std::size_t length = 0) {
  GltfFieldRule rule = field(pattern, Kind::array);
  rule.length = length;
  return rule;
}
// An array the schema gives minItems 1.
GltfFieldRule listing(std::string_view pattern) {
  GltfFieldRule rule = array(pattern);
  rule.min_length = 1;
  return rule;
}
GltfFieldRule nonzero(GltfFieldRule rule) {
  rule.nonzero = true;
  return rule;
}
GltfFieldRule number(std::string_view pattern, double minimum, double maximum,
                     bool above_minimum = false) {
  GltfFieldRule rule = field(pattern, Kind::number);
  rule.minimum = minimum;
  rule.maximum = maximum;
  rule.above_minimum = above_minimum;
  return rule;
}
GltfFieldRule whole(std::string_view pattern, double minimum, double maximum = 1e300) {
  GltfFieldRule rule = number(pattern, minimum, maximum);
  rule.kind = Kind::integer;
  return rule;
}
// An index is at most 2^53 - 1, the largest whole number a double holds exactly: beyond it no
// array can reach and the index could not be converted to an integer for the range check.
GltfFieldRule index(std::string_view pattern, std::string_view target) {
  GltfFieldRule rule = whole(pattern, 0.0, 9007199254740991.0);
  rule.indexes = target;
  return rule;
}
GltfFieldRule one_of(std::string_view pattern, Kind kind, std::string_view choices) {
  GltfFieldRule rule = field(pattern, kind);
  rule.choices = choices;
  return rule;
}
GltfFieldRule special(std::string_view pattern, GltfSpecialCheck check) {
  GltfFieldRule rule = field(pattern, Kind::string);
  rule.special = check;
  return rule;
}
GltfFieldRule required(GltfFieldRule rule) {
  rule.required = true;
  return rule;
}

// The table: what levrt reads, plus the indices between the arrays it reads (a reference past
// its array is refused even where levrt would not follow it, as the validator does).
const std::vector<GltfFieldRule>& rules() {
  static const std::vector<GltfFieldRule> table = {
      required(object("asset")),
      required(special("asset.version", GltfSpecialCheck::version)),
      special("asset.minVersion", GltfSpecialCheck::min_version),
      listing("extensionsUsed"),
      special("extensionsUsed[]", GltfSpecialCheck::used_extension),
      listing("extensionsRequired"),
      special("extensionsRequired[]", GltfSpecialCheck::required_extension),
      index("scene", "scenes"),
      listing("scenes"),
      object("scenes[]"),
      listing("scenes[].nodes"),
      index("scenes[].nodes[]", "nodes"),
      // Nodes.
      listing("nodes"),
      object("nodes[]"),
      listing("nodes[].children"),
      index("nodes[].children[]", "nodes"),
      index("nodes[].mesh", "meshes"),
      index("nodes[].camera", "cameras"),
      index("nodes[].skin", "skins"),
      array("nodes[].matrix", 16),
      number("nodes[].matrix[]", -1e300, 1e300),
      array("nodes[].translation", 3),
      number("nodes[].translation[]", -1e300, 1e300),
      array("nodes[].rotation", 4),
      number("nodes[].rotation[]", -1.0, 1.0),
      array("nodes[].scale", 3),
      number("nodes[].scale[]", -1e300, 1e300),
      object("nodes[].extensions.KHR_lights_punctual"),
      required(index("nodes[].extensions.KHR_lights_punctual.light",
                     "extensions.KHR_lights_punctual.lights")),
      // KHR_lights_punctual.
      object("extensions.KHR_lights_punctual"),
      listing("extensions.KHR_lights_punctual.lights"),
      object("extensions.KHR_lights_punctual.lights[]"),
      required(one_of("extensions.KHR_lights_punctual.lights[].type", Kind::string,
                      "point spot directional")),
      array("extensions.KHR_lights_punctual.lights[].color", 3),
      number("extensions.KHR_lights_punctual.lights[].color[]", 0.0, 1.0),
      number("extensions.KHR_lights_punctual.lights[].intensity", 0.0, 1e300),
      number("extensions.KHR_lights_punctual.lights[].range", 0.0, 1e300, true),
      object("extensions.KHR_lights_punctual.lights[].spot"),
      number("extensions.KHR_lights_punctual.lights[].spot.innerConeAngle", 0.0, kHalfPi),
      number("extensions.KHR_lights_punctual.lights[].spot.outerConeAngle", 0.0, kHalfPi, true),
      // Meshes.
      listing("meshes"),
      object("meshes[]"),
      required(listing("meshes[].primitives")),
      object("meshes[].primitives[]"),
      required(object("meshes[].primitives[].attributes")),
      index("meshes[].primitives[].attributes.*", "accessors"),
      index("meshes[].primitives[].indices", "accessors"),
      index("meshes[].primitives[].material", "materials"),
      whole("meshes[].primitives[].mode", 0.0, 6.0),
      listing("meshes[].primitives[].targets"),
      object("meshes[].primitives[].targets[]"),
      index("meshes[].primitives[].targets[].*", "accessors"),
      // Accessors, buffer views, buffers.
      listing("accessors"),
      object("accessors[]"),
      index("accessors[].bufferView", "bufferViews"),
      whole("accessors[].byteOffset", 0.0),
      required(one_of("accessors[].componentType", Kind::integer, "5120 5121 5122 5123 5125 5126")),
      field("accessors[].normalized", Kind::boolean),
      required(whole("accessors[].count", 1.0)),
      required(one_of("accessors[].type", Kind::string, "SCALAR VEC2 VEC3 VEC4 MAT2 MAT3 MAT4")),
      object("accessors[].sparse"),
      required(whole("accessors[].sparse.count", 1.0)),
      required(object("accessors[].sparse.indices")),
      required(index("accessors[].sparse.indices.bufferView", "bufferViews")),
      whole("accessors[].sparse.indices.byteOffset", 0.0),
      required(one_of("accessors[].sparse.indices.componentType", Kind::integer, "5121 5123 5125")),
      required(object("accessors[].sparse.values")),
      required(index("accessors[].sparse.values.bufferView", "bufferViews")),
      whole("accessors[].sparse.values.byteOffset", 0.0),
      listing("bufferViews"),
      object("bufferViews[]"),
      required(index("bufferViews[].buffer", "buffers")),
      whole("bufferViews[].byteOffset", 0.0),
      required(whole("bufferViews[].byteLength", 1.0)),
      whole("bufferViews[].byteStride", 4.0, 252.0),
      listing("buffers"),
      object("buffers[]"),
      field("buffers[].uri", Kind::string),
      required(whole("buffers[].byteLength", 1.0)),
      // Materials, textures, images, samplers.
      listing("materials"),
      object("materials[]"),
      object("materials[].pbrMetallicRoughness"),
      array("materials[].pbrMetallicRoughness.baseColorFactor", 4),
      number("materials[].pbrMetallicRoughness.baseColorFactor[]", 0.0, 1.0),
      number("materials[].pbrMetallicRoughness.metallicFactor", 0.0, 1.0),
      number("materials[].pbrMetallicRoughness.roughnessFactor", 0.0, 1.0),
      object("materials[].pbrMetallicRoughness.baseColorTexture"),
      required(index("materials[].pbrMetallicRoughness.baseColorTexture.index", "textures")),
      whole("materials[].pbrMetallicRoughness.baseColorTexture.texCoord", 0.0),
      required(
          index("materials[].pbrMetallicRoughness.metallicRoughnessTexture.index", "textures")),
      required(index("materials[].normalTexture.index", "textures")),
      required(index("materials[].occlusionTexture.index", "textures")),
      required(index("materials[].emissiveTexture.index", "textures")),
      whole("materials[].emissiveTexture.texCoord", 0.0),
      array("materials[].emissiveFactor", 3),
      number("materials[].emissiveFactor[]", 0.0, 1.0),
      // An unknown alpha mode is the validator's warning: levrt draws it opaque, with a warning.
      field("materials[].alphaMode", Kind::string),
      number("materials[].alphaCutoff", 0.0, 1e300),
      field("materials[].doubleSided", Kind::boolean),
      number("materials[].extensions.KHR_materials_transmission.transmissionFactor", 0.0, 1.0),
      number("materials[].extensions.KHR_materials_ior.ior", 0.0, 1e300),
      object("materials[].extensions.KHR_materials_emissive_strength"),
      number("materials[].extensions.KHR_materials_emissive_strength.emissiveStrength", 0.0, 1e300),
      object("materials[].extensions.KHR_materials_unlit"),
      listing("textures"),
      object("textures[]"),
      index("textures[].source", "images"),
      index("textures[].sampler", "samplers"),
      listing("images"),
      object("images[]"),
      field("images[].uri", Kind::string),
      index("images[].bufferView", "bufferViews"),
      one_of("images[].mimeType", Kind::string, "image/jpeg image/png"),
      listing("samplers"),
      object("samplers[]"),
      // An unknown wrap mode is the validator's warning, not an error: levrt repeats.
      whole("samplers[].wrapS", 0.0),
      whole("samplers[].wrapT", 0.0),
      // Cameras. A perspective zfar is not read (rays have no far plane), and tinygltf's writer
      // puts 0 there: docs/gltf_conformance.md lists it.
      listing("cameras"),
      object("cameras[]"),
      // Another camera type is only the validator's warning, but tinygltf cannot read one
      // (docs/gltf_conformance.md): refused here, by its glTF path.
      required(one_of("cameras[].type", Kind::string, "perspective orthographic")),
      object("cameras[].perspective"),
      required(number("cameras[].perspective.yfov", 0.0, 1e300, true)),
      required(number("cameras[].perspective.znear", 0.0, 1e300, true)),
      number("cameras[].perspective.aspectRatio", 0.0, 1e300, true),
      object("cameras[].orthographic"),
      // Zero is the validator's error; a negative magnitude only its warning (levrt reads |ymag|).
      required(nonzero(number("cameras[].orthographic.xmag", -1e300, 1e300))),
      required(nonzero(number("cameras[].orthographic.ymag", -1e300, 1e300))),
      required(number("cameras[].orthographic.zfar", 0.0, 1e300, true)),
      required(number("cameras[].orthographic.znear", 0.0, 1e300)),
      // Animations (not read: levrt draws the first frame), for the schema's minItems.
      listing("animations"),
      // Skins (not drawn, but their node and accessor indices are references).
      listing("skins"),
      object("skins[]"),
      required(listing("skins[].joints")),
      index("skins[].joints[]", "nodes"),
      index("skins[].skeleton", "nodes"),
      index("skins[].inverseBindMatrices", "accessors"),
  };
  return table;
}

const std::unordered_map<std::string_view, const GltfFieldRule*>& rule_of_pattern() {
  static const std::unordered_map<std::string_view, const GltfFieldRule*> map = [] {
    std::unordered_map<std::string_view, const GltfFieldRule*> m;
    for (const GltfFieldRule& rule : rules()) m.emplace(rule.pattern, &rule);
    return m;
  }();
  return map;
}

std::string parent_pattern(std::string_view pattern) {
  const std::size_t dot = pattern.rfind('.');
  if (pattern.size() >= 2 && pattern.substr(pattern.size() - 2) == "[]")
    return std::string(pattern.substr(0, pattern.size() - 2));
  return dot == std::string_view::npos ? std::string() : std::string(pattern.substr(0, dot));
}

std::string kind_name(Kind kind) {
  switch (kind) {
    case Kind::null:
      return "null";
    case Kind::boolean:
      return "a boolean";
    case Kind::integer:
      return "a whole number";
    case Kind::number:
      return "a number";
    case Kind::string:
      return "a string";
    case Kind::object:
      return "an object";
    default:
      return "an array";
  }
}

bool fits(Kind wanted, Kind got) {
  return wanted == got || (wanted == Kind::number && got == Kind::integer);
}

bool is_choice(std::string_view choices, std::string_view value) {
  std::size_t start = 0;
  while (start < choices.size()) {
    std::size_t end = choices.find(' ', start);
    if (end == std::string_view::npos) end = choices.size();
    if (choices.substr(start, end - start) == value) return true;
    start = end + 1;
  }
  return false;
}

std::string interval_text(const GltfFieldRule& rule) {
  auto text = [](double v) {
    if (v == kHalfPi) return std::string("pi/2");
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  std::string out;
  if (rule.minimum > -1e300)
    out += (rule.above_minimum ? " above " : " from ") + text(rule.minimum);
  if (rule.maximum < 1e300) out += " to " + text(rule.maximum);
  return out;
}

// "MAJOR.MINOR" as two numbers, or false.
bool read_version(std::string_view text, long& major, long& minor) {
  const std::size_t dot = text.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == text.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (i != dot && (text[i] < '0' || text[i] > '9')) return false;
  }
  if (dot > 6 || text.size() - dot > 7) return false;
  major = std::stol(std::string(text.substr(0, dot)));
  minor = std::stol(std::string(text.substr(dot + 1)));
  return true;
}

std::string version_problem(const GltfFieldRule& rule, std::string_view text) {
  long major = 0, minor = 0;
  if (!read_version(text, major, minor)) return "a version is written MAJOR.MINOR, as \"2.0\"";
  if (rule.special == GltfSpecialCheck::version && major != 2) return "levrt reads glTF 2.x only";
  if (rule.special == GltfSpecialCheck::min_version && (major > 2 || (major == 2 && minor > 0)))
    return "the file needs a reader of glTF " + std::string(text) + "; levrt reads 2.0";
  return {};
}

}  // namespace

std::string gltf_member_pattern(const std::string& container, std::string_view key, bool in_array) {
  if (in_array) return container + "[]";
  if (container.empty()) return std::string(key);
  std::string pattern = container;
  pattern += '.';
  pattern += key;
  return pattern;
}

const GltfFieldRule* find_gltf_field_rule(const std::string& container, std::string_view key,
                                          bool in_array) {
  const auto& map = rule_of_pattern();
  const auto found = map.find(gltf_member_pattern(container, key, in_array));
  if (found != map.end()) return found->second;
  if (in_array) return nullptr;
  const auto any = map.find(gltf_member_pattern(container, "*", false));
  return any == map.end() ? nullptr : any->second;
}

std::string gltf_field_problem(const GltfFieldRule& rule, const GltfJsonValue& value) {
  if (!fits(rule.kind, value.kind)) return kind_name(rule.kind) + " is expected";
  if (value.kind == Kind::integer || value.kind == Kind::number) {
    const bool below =
        rule.above_minimum ? !(value.number > rule.minimum) : !(value.number >= rule.minimum);
    if (!std::isfinite(value.number) || below || value.number > rule.maximum)
      return kind_name(rule.kind) + interval_text(rule) + " is expected";
  }
  if (rule.nonzero && value.number == 0.0)
    return kind_name(rule.kind) + " other than 0 is expected";
  if (!rule.choices.empty() && !is_choice(rule.choices, value.text))
    return "one of " + std::string(rule.choices) + " is expected";
  switch (rule.special) {
    case GltfSpecialCheck::version:
    case GltfSpecialCheck::min_version:
      return version_problem(rule, value.text);
    case GltfSpecialCheck::required_extension:
      if (!is_honoured_gltf_extension(value.text))
        return "an extension levrt cannot honour is required; it honours " +
               honoured_gltf_extensions_text();
      return {};
    default:
      return {};
  }
}

const std::vector<std::string_view>& required_gltf_members(const std::string& object) {
  static const std::map<std::string, std::vector<std::string_view>, std::less<>> members = [] {
    std::map<std::string, std::vector<std::string_view>, std::less<>> m;
    for (const GltfFieldRule& rule : rules()) {
      if (!rule.required) continue;
      const std::string parent = parent_pattern(rule.pattern);
      const std::string_view key = rule.pattern.substr(parent.empty() ? 0 : parent.size() + 1);
      m[parent].push_back(key);
    }
    return m;
  }();
  static const std::vector<std::string_view> none;
  const auto found = members.find(object);
  return found == members.end() ? none : found->second;
}

bool is_gltf_index_target(const std::string& array) {
  static const std::set<std::string_view, std::less<>> targets = [] {
    std::set<std::string_view, std::less<>> s;
    for (const GltfFieldRule& rule : rules()) {
      if (!rule.indexes.empty()) s.insert(rule.indexes);
    }
    return s;
  }();
  return targets.count(std::string_view(array)) != 0;
}

bool is_honoured_gltf_extension(std::string_view name) {
  for (const std::string_view honoured : kHonouredExtensions) {
    if (name == honoured) return true;
  }
  return false;
}

std::string honoured_gltf_extensions_text() {
  std::string text;
  for (const std::string_view honoured : kHonouredExtensions)
    text += (text.empty() ? "" : ", ") + std::string(honoured);
  return text;
}

}  // namespace scenes
