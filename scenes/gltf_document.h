// The check a glTF file's JSON passes before tinygltf parses it. tinygltf hands the text to
// nlohmann's recursive parser, truncates integers to int (a light index of 2^32 became light 0)
// and reads any file a URI names; so first nlohmann's iterative SAX parser reads the JSON (the
// .gltf whole, or a .glb's JSON chunk) with the scene file's limits (kMaxJsonDepth levels,
// kMaxJsonValues values), refusing a NUL byte and anything after the JSON, and checks as it reads:
// every index is a whole number in [0, 2^31 - 1], every offset, length, stride and count a whole
// number in [0, 2^53], `mode` one of the seven modes, `componentType` one of the six types; every
// field levrt reads of the type, range and length gltf_schema.h's table gives (no empty array where
// glTF asks for elements, no extension listed twice), every index inside
// its array, asset.version 2.x, no minVersion above 2.0, no required extension levrt cannot
// honour; and every buffer and image URI either a data URI or a regular file inside the glTF's
// folder (scene_folder.h), charged to the scene's budget by its size before anything reads it. The
// `extras` of any object and the extensions this reader does not know (not KHR_) are not checked.
// Each refusal is one line "FILE: glTF.path: value (what is wrong)", the path as in
// `nodes[3].extensions.KHR_lights_punctual.light`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "scenes/gltf_budget.h"
#include "scenes/scene_folder.h"

namespace scenes {

// The external files a checked document names: decoded relative path -> the file found.
using GltfExternalFiles = std::map<std::string, FolderFile>;

// What a checked document tells the import: its external files, and the extensions it uses that
// levrt ignores (for the one warning line).
struct GltfDocumentFacts {
  GltfExternalFiles files;
  std::vector<std::string> ignored_extensions;
};

// `bytes` is the whole file (binary: a .glb), `path` names it in messages, `folder` is where its
// URIs resolve. Charges the JSON values and the external files to `budget`.
GltfDocumentFacts check_gltf_document(const std::string& bytes, bool binary,
                                      const std::string& path, const std::string& folder,
                                      GltfBudget& budget);

// Whether `bytes` begin with the binary glTF magic "glTF": the content, not the file's name,
// tells a .glb from a .gltf (a JSON text never starts with 'g').
bool is_glb(const std::string& bytes);

// The JSON a .glb carries in its first chunk, refused (one line naming `path`) when the header
// (magic, version 2, a length equal to the file's) or the chunk's bounds are wrong.
std::string glb_json_chunk(const std::string& bytes, const std::string& path);

}  // namespace scenes
