// The fields of a glTF 2.0 document that levrt reads, as one table: the JSON type each must have,
// its range or its allowed values, whether it is required, the array an index field points into,
// and the checks of asset.version, asset.minVersion, extensionsRequired and extensionsUsed. The
// pre-parse pass (gltf_document.h) checks every value of the document against this table, so a
// wrong type (`"intensity": "50"`), a value out of range (`"range": 0`) or an index past its
// array is refused with its glTF path instead of becoming one of tinygltf's silent defaults.
// A field is named by its pattern: the path with every array index written `[]` and, where any
// member name goes (a primitive's attributes), `*`: `meshes[].primitives[].attributes.*`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace scenes {

enum class GltfJsonKind { null, boolean, integer, number, string, object, array };

// A JSON value as the table checks it: `number` for numbers (integer: a whole one), `text` the
// string's characters or the number as written.
struct GltfJsonValue {
  GltfJsonKind kind = GltfJsonKind::null;
  double number = 0.0;
  std::string_view text;
};

// The checks that are more than a type and an interval.
enum class GltfSpecialCheck { none, version, min_version, required_extension, used_extension };

struct GltfFieldRule {
  std::string_view pattern;
  GltfJsonKind kind = GltfJsonKind::object;  // integer also takes a number written 3.0
  double minimum = -1e300;                   // numbers: the interval allowed
  double maximum = 1e300;
  bool above_minimum = false;  // the minimum itself is excluded
  std::string_view choices;    // strings and integers: the allowed values, space-separated
  std::string_view indexes;    // an index: the pattern of the array it points into
  std::size_t length = 0;      // an array: its exact number of elements (0: any)
  std::size_t min_length = 0;  // an array: its least number of elements (glTF's minItems)
  bool nonzero = false;        // a number: 0 is refused (an orthographic camera's xmag, ymag)
  bool required = false;       // the member must be in its object
  GltfSpecialCheck special = GltfSpecialCheck::none;
};

// The rule for the value a member `key` of an object (or, with in_array, an element of an array)
// whose pattern is `container` holds; nullptr when levrt does not read it.
const GltfFieldRule* find_gltf_field_rule(const std::string& container, std::string_view key,
                                          bool in_array);

// The pattern of that value: `container.key`, or `container[]`.
std::string gltf_member_pattern(const std::string& container, std::string_view key, bool in_array);

// What is wrong with `value` under `rule`, as "(...)" text naming what is expected; "" when
// it conforms. A required extension levrt cannot honour and a version it cannot read are wrong.
std::string gltf_field_problem(const GltfFieldRule& rule, const GltfJsonValue& value);

// The members an object of pattern `object` must have.
const std::vector<std::string_view>& required_gltf_members(const std::string& object);

// Whether some index points into the array of pattern `array` (its length is then counted).
bool is_gltf_index_target(const std::string& array);

// The extensions levrt honours: it reads them and renders what they mean (for
// KHR_mesh_quantization, the byte and short vertex attributes it allows). Any other one in
// extensionsRequired refuses the file; in extensionsUsed, it is ignored with one warning.
bool is_honoured_gltf_extension(std::string_view name);
std::string honoured_gltf_extensions_text();

}  // namespace scenes
