// The binary container as gltf_document.h reads it: the content tells a .glb from a .gltf (the
// 'glTF' magic, whatever the file is called), and a header whose version is not 2 or whose
// length disagrees with the file's size is refused with one line naming the file.
#include "scenes/gltf_document.h"

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "scenes/gltf_scene.h"
#include "tests/support/gltf_refusal.h"

namespace {

const std::string kJson =
    R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}},
    "scenes": [{"nodes": [0]}], "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]})";

std::string word(std::uint32_t v) {
  std::string bytes(4, '\0');
  for (int i = 0; i < 4; ++i)
    bytes[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xffu);
  return bytes;
}

// `json` as a binary glTF: header (magic, version, length plus `length_delta`), one JSON chunk.
std::string glb_with_header(std::string json, std::uint32_t version = 2,
                            std::int64_t length_delta = 0) {
  while (json.size() % 4 != 0) json += ' ';
  const auto length =
      static_cast<std::uint32_t>(20 + static_cast<std::int64_t>(json.size()) + length_delta);
  return "glTF" + word(version) + word(length) + word(static_cast<std::uint32_t>(json.size())) +
         "JSON" + json;
}

TEST(GltfDocument, TheContentNotTheNameTellsBinaryFromText) {
  EXPECT_TRUE(scenes::is_glb(glb_with_header(kJson)));
  EXPECT_FALSE(scenes::is_glb(kJson));
  EXPECT_FALSE(scenes::is_glb("glT"));
  for (const std::string& bytes : {glb_with_header(kJson), kJson}) {
    for (const std::string name : {"named.gltf", "named.glb"}) {
      EXPECT_EQ(scenes::parse_gltf_scene(bytes, name).root.children.size(), 1u) << name;
    }
  }
}

TEST(GltfDocument, AHeaderThatDisagreesWithTheFileIsRefused) {
  // A short header length: the file goes on past where the header says it ends.
  std::string longer = glb_with_header(kJson) + "    ";
  levrt_test::expect_gltf_refused(longer, "short.glb",
                                  "binary glTF: header length " +
                                      std::to_string(longer.size() - 4) + " bytes, the file has " +
                                      std::to_string(longer.size()));
  levrt_test::expect_gltf_refused(glb_with_header(kJson, 2, 8), "long.glb",
                                  "binary glTF: header length");
  levrt_test::expect_gltf_refused(glb_with_header(kJson, 1), "v1.glb",
                                  "binary glTF: header version 1");
}

}  // namespace
