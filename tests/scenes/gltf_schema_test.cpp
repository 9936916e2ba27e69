// The schema the pre-parse pass checks (scenes/gltf_schema.h) through parse_gltf_scene: required
// extensions levrt cannot honour, versions it cannot read, wrong JSON types, values out of range,
// missing required members, indices past their array, empty arrays where glTF asks for elements,
// extensions listed twice and cameras without their type's object or with zfar not beyond znear
// are refused with one line naming the glTF path and the value; extensions used but ignored give
// one warning line; files that conform (versions 2.x, honoured extensions required, whole numbers
// written as 3.0) are read.
#include "scenes/gltf_schema.h"

#include <algorithm>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "scenes/gltf_scene.h"
#include "tests/support/gltf_refusal.h"

namespace {

constexpr char kSchemaPath[] = "schema.gltf";

// One point light on one node; `top` adds members to the document, `light` replaces the light.
std::string gltf(
    const std::string& top, const std::string& light = R"({"type": "point"})",
    const std::string& node = R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})",
    const std::string& asset = R"({"version": "2.0"})") {
  return R"({"asset": )" + asset + R"(, "extensions": {"KHR_lights_punctual": {"lights": [)" +
         light + R"(]}}, "scenes": [{"nodes": [0]}], "nodes": [)" + node + "]" + top + "}";
}

std::string warnings_of(const std::string& text) {
  testing::internal::CaptureStderr();
  (void)scenes::parse_gltf_scene(text, kSchemaPath);
  return testing::internal::GetCapturedStderr();
}

TEST(GltfSchema, RequiredExtensionsLevrtCannotHonourAreRefusedByName) {
  for (const std::string name : {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                 "KHR_texture_basisu", "EXT_made_up"}) {
    const std::string top = R"(, "extensionsUsed": ["KHR_lights_punctual", ")" + name +
                            R"("], "extensionsRequired": ["KHR_lights_punctual", ")" + name +
                            R"("])";
    levrt_test::expect_gltf_refused(gltf(top), kSchemaPath,
                                    "extensionsRequired[1]: '" + name + "' (an extension");
  }
}

TEST(GltfSchema, EmptyArraysAndRepeatedExtensionsAreRefusedByPath) {
  const std::pair<std::string, std::string> cases[] = {
      {R"(, "materials": [])", "materials: an empty array (glTF asks for at least 1"},
      {R"(, "animations": [])", "animations: an empty array"},
      {R"(, "extensionsRequired": [])", "extensionsRequired: an empty array"},
      {R"(, "extensionsUsed": ["KHR_lights_punctual", "KHR_lights_punctual"])",
       "extensionsUsed[1]: 'KHR_lights_punctual' (listed twice in extensionsUsed)"},
      {R"(, "extensionsUsed": ["KHR_lights_punctual"], )"
       R"("extensionsRequired": ["KHR_lights_punctual", "KHR_lights_punctual"])",
       "extensionsRequired[1]: 'KHR_lights_punctual' (listed twice in extensionsRequired)"},
      {R"(, "cameras": [{"type": "orthographic"}])",
       "cameras[0].orthographic: missing (a member a camera of type orthographic requires)"},
      {R"(, "cameras": [{"type": "orthographic", "orthographic": )"
       R"({"xmag": 1, "ymag": 1, "znear": 2, "zfar": 1.5}}])",
       "cameras[0].orthographic.zfar: 1.5 (beyond znear 2 is expected)"},
      {R"(, "cameras": [{"type": "orthographic", "orthographic": )"
       R"({"xmag": 1, "ymag": 0, "znear": 0, "zfar": 1}}])",
       "cameras[0].orthographic.ymag: 0 (a number other than 0 is expected)"},
      {R"(, "materials": [{"alphaCutoff": -1}])", "materials[0].alphaCutoff: -1 (a number"},
      {R"(, "materials": [{"doubleSided": "yes"}])",
       "materials[0].doubleSided: 'yes' (a boolean is expected)"},
      {R"(, "materials": [{"emissiveFactor": [2, 0, 0]}])", "materials[0].emissiveFactor[0]: 2"},
  };
  for (const auto& [top, problem] : cases)
    levrt_test::expect_gltf_refused(gltf(top), kSchemaPath, problem);
  // The light list itself.
  levrt_test::expect_gltf_refused(
      R"({"asset": {"version": "2.0"}, "extensions": {"KHR_lights_punctual": {"lights": []}}})",
      kSchemaPath, "extensions.KHR_lights_punctual.lights: an empty array");
}

TEST(GltfSchema, HonouredRequiredExtensionsAreRead) {
  const std::string top = R"(, "extensionsUsed": ["KHR_lights_punctual"], )"
                          R"("extensionsRequired": ["KHR_lights_punctual"])";
  EXPECT_EQ(warnings_of(gltf(top)), "");
  levrt_test::expect_gltf_refused(
      gltf(R"(, "extensionsRequired": ["KHR_lights_punctual"])"), kSchemaPath,
      "extensionsRequired[0]: 'KHR_lights_punctual' (required but not in extensionsUsed)");
  EXPECT_TRUE(scenes::is_honoured_gltf_extension("KHR_lights_punctual"));
  EXPECT_FALSE(scenes::is_honoured_gltf_extension("KHR_draco_mesh_compression"));
}

TEST(GltfSchema, IgnoredUsedExtensionsGiveOneWarningLine) {
  const std::string top =
      R"(, "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform", "EXT_made_up"])";
  const std::string warnings = warnings_of(gltf(top));
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 1) << warnings;
  EXPECT_EQ(
      warnings.rfind(std::string(kSchemaPath) + ": warning: extensionsUsed: KHR_texture_transform, "
                                                "EXT_made_up ignored",
                     0),
      0u)
      << warnings;
}

TEST(GltfSchema, VersionsOtherThanTwoAndMinVersionsAboveTwoPointZeroAreRefused) {
  const std::pair<std::string, std::string> refused[] = {
      {R"({"version": "1.0"})", "asset.version: '1.0' (levrt reads glTF 2.x only)"},
      {R"({"version": "3.0"})", "asset.version: '3.0' (levrt reads glTF 2.x only)"},
      {R"({"version": "2"})", "asset.version: '2' (a version is written MAJOR.MINOR"},
      {R"({"version": 2.0})", "asset.version: 2.0 (a string is expected)"},
      {R"({"version": "2.0", "minVersion": "2.1"})", "asset.minVersion: '2.1' (the file needs"},
      {R"({"generator": "x"})", "asset.version: missing (a member glTF requires)"},
  };
  for (const auto& [asset, problem] : refused)
    levrt_test::expect_gltf_refused(
        gltf("", R"({"type": "point"})", R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})",
             asset),
        kSchemaPath, problem);
  for (const std::string asset :
       {R"({"version": "2.0", "minVersion": "2.0"})", R"({"version": "2.1"})"}) {
    EXPECT_NO_THROW((void)scenes::parse_gltf_scene(
        gltf("", R"({"type": "point"})", R"({"extensions": {"KHR_lights_punctual": {"light": 0}}})",
             asset),
        kSchemaPath))
        << asset;
  }
}

TEST(GltfSchema, WrongTypesAndValuesOutOfRangeAreRefusedWithTheGltfPath) {
  const std::string lights = "extensions.KHR_lights_punctual.lights[0].";
  const std::pair<std::string, std::string> refused[] = {
      {R"({"type": "point", "intensity": "50"})",
       lights + "intensity: '50' (a number is expected)"},
      {R"({"type": "point", "range": "3"})", lights + "range: '3' (a number is expected)"},
      {R"({"type": "point", "range": 0})", lights + "range: 0 (a number above 0 is expected)"},
      {R"({"type": "point", "range": null})", lights + "range: null (a number is expected)"},
      {R"({"type": "point", "color": [1, 1]})", lights + "color: 2 values (3 are expected)"},
      {R"({"type": "point", "color": [1, 2, 1]})", lights + "color[1]: 2 (a number from 0 to 1"},
      {R"({"type": 1})", lights + "type: 1 (a string is expected)"},
      {R"({"intensity": 1})", lights + "type: missing (a member glTF requires)"},
      {R"({"type": "spot", "spot": 0.5})", lights + "spot: 0.5 (an object is expected)"},
  };
  for (const auto& [light, problem] : refused)
    levrt_test::expect_gltf_refused(gltf("", light), kSchemaPath, problem);
}

TEST(GltfSchema, IndicesPastTheirArrayAreRefusedWhereverTheArrayComes) {
  const std::string light = R"({"type": "point"})";
  const std::pair<std::string, std::string> refused[] = {
      {gltf("", light, R"({"extensions": {"KHR_lights_punctual": {"light": 3}}})"),
       "nodes[0].extensions.KHR_lights_punctual.light: 3 (an index past the 1 element(s) of "
       "extensions.KHR_lights_punctual.lights)"},
      {gltf("", light, R"({"mesh": 0})"), "nodes[0].mesh: 0 (an index past the 0 element(s)"},
      {gltf(R"(, "scene": 1)"), "scene: 1 (an index past the 1 element(s) of scenes)"},
      {gltf("", light, R"({"children": [4]})"), "nodes[0].children[0]: 4 (an index past"},
      {gltf("", light, R"({"mesh": "0"})"), "nodes[0].mesh: '0' (a whole number is expected)"},
      {gltf("", light, R"({"translation": [0, "1", 0]})"),
       "nodes[0].translation[1]: '1' (a number is expected)"},
      {gltf("", light, R"({"extensions": {"KHR_lights_punctual": {}}})"),
       "nodes[0].extensions.KHR_lights_punctual.light: missing"},
  };
  for (const auto& [text, problem] : refused)
    levrt_test::expect_gltf_refused(text, kSchemaPath, problem);
}

TEST(GltfSchema, AWholeNumberWrittenWithAFractionIsAnIndex) {
  const scenes::SceneDescription scene =
      scenes::parse_gltf_scene(gltf("", R"({"type": "point", "intensity": 2})",
                                    R"({"extensions": {"KHR_lights_punctual": {"light": 0.0}}})"),
                               kSchemaPath);
  EXPECT_EQ(scene.root.children.size(), 1u);
}

TEST(GltfSchema, TheTableAnswersByPattern) {
  const scenes::GltfFieldRule* range =
      scenes::find_gltf_field_rule("extensions.KHR_lights_punctual.lights[]", "range", false);
  ASSERT_NE(range, nullptr);
  EXPECT_EQ(scenes::gltf_field_problem(*range, {scenes::GltfJsonKind::integer, 3.0, "3"}), "");
  EXPECT_NE(scenes::gltf_field_problem(*range, {scenes::GltfJsonKind::integer, 0.0, "0"}), "");
  const scenes::GltfFieldRule* attribute =
      scenes::find_gltf_field_rule("meshes[].primitives[].attributes", "TEXCOORD_7", false);
  ASSERT_NE(attribute, nullptr);
  EXPECT_EQ(attribute->indexes, "accessors");
  EXPECT_EQ(scenes::find_gltf_field_rule("nodes[]", "name", false), nullptr);
  EXPECT_TRUE(scenes::is_gltf_index_target("nodes"));
  const auto& required = scenes::required_gltf_members("accessors[]");
  EXPECT_NE(std::find(required.begin(), required.end(), "componentType"), required.end());
}

}  // namespace
