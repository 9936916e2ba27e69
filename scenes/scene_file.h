// Scene files: the scene description (scene_description.h) as JSON, format in scenes/README.md.
// Reading checks everything before anything is built, and every problem becomes one line
// "FILE: /json/path: problem (value)" in a std::invalid_argument: unknown keys, wrong types,
// missing fields, values out of range, undefined masters or materials, instance cycles, and the
// limits of scene_instantiation.h. The file size and the JSON nesting depth are checked while
// reading, before any deep structure exists, so a huge or deeply nested file fails cleanly; so is
// the number of JSON values (kMaxJsonValues), which bounds the memory the document takes. A NUL
// byte anywhere is refused with its offset, since it would silently end the text for C readers.
// Writing is exact: every float is written so that it reads back as the same float, so a scene
// written and read back instantiates to the same scene, bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "scenes/gltf_scene.h"
#include "scenes/scene_description.h"

namespace scenes {

inline constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{64} << 20;
inline constexpr int kMaxJsonDepth = 256;
// JSON values (numbers, strings, objects, arrays...) a scene file may hold. The document costs
// about 110 bytes per value in memory (2.3 GB for the 21 million values of a 64 MiB file of
// `{},`), so this bounds a file's document near 110 MB plus its strings, whatever its shape; the
// largest built-in scene exported (hall level 8) has about 2,000 values.
inline constexpr std::size_t kMaxJsonValues = 1'000'000;
inline constexpr int kSceneFileVersion = 1;

// Text as it may appear in a one-line message, the one helper for every message that quotes user
// text (a flag's value, a file name, a scene, node or light name): control characters and DEL
// become escapes (\n, \t, \r, \x1b, ...), the C1 controls and the invisible format characters
// that reorder or hide text (right-to-left overrides and isolates, zero-width characters, line
// separators, U+FEFF) become \u and four hex digits (\u202e), and a byte that is no part of a UTF-8
// character becomes \xNN. So a name can neither break the line, drive the terminal, nor show other
// text than it holds; other characters (accented letters, CJK) stay as they are. Escaping twice
// changes nothing (no such character is left), so the command line may escape a whole message again
// at its boundary.
std::string escape_control_characters(std::string_view text);

// True for names ending in ".json", ".gltf" or ".glb" (gltf_scene.h): what --scene takes as a
// file rather than a model name.
bool is_scene_file_name(std::string_view name);

// Parses and validates; `source` names the text in messages (the file name).
SceneDescription parse_scene_json(const std::string& text, const std::string& source);

// What a file's reading may be asked: which camera (gltf_scene.h). A JSON scene file has one
// camera, 0.
struct SceneFileOptions {
  int camera = 0;
};

// Reads a file of at most kMaxSceneFileBytes (a binary glTF: kMaxGltfSceneBytes), then
// parse_scene_json (or parse_gltf_scene). A missing name in the file becomes the file's stem.
SceneDescription load_scene_file(const std::string& path, const SceneFileOptions& options = {});

// The description as scene-file text (validated first; throws like validate_description). Scene
// files hold no triangle meshes: a description with mesh nodes (a glTF import) throws this.
inline constexpr std::string_view kMeshNotWritable =
    "/root: triangle meshes (from glTF) cannot be written to a scene file";
// Nor directional lights (glTF suns).
inline constexpr std::string_view kDirectionalNotWritable =
    "/directional_lights: directional lights (from glTF) cannot be written to a scene file";
std::string scene_file_json(const SceneDescription& scene);

}  // namespace scenes
