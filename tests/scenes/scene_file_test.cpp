// Scene files: every kind of bad input is refused with one line naming the JSON path and the
// problem; huge or deeply nested files fail cleanly; a flat list of lights gets a hierarchy.
#include "scenes/scene_file.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/temp_dir.h"

namespace {

using json = nlohmann::json;

// A small valid scene: a lamp master (a bulb and a light) hung over a floor.
json valid_scene() {
  return json::parse(R"({
    "levrt_scene": 1,
    "camera": {"position": [0, -10, 5], "target": [0, 0, 0]},
    "materials": [{"name": "m", "kd": 0.5}],
    "masters": [{"name": "lamp", "node": {"type": "union", "children": [
      {"type": "sphere", "material": "m", "centre": [0, 0, 0.3], "radius": 0.2},
      {"type": "point_light", "intensity": [1, 1, 1]}]}}],
    "root": {"type": "union", "children": [
      {"type": "affine", "translate": [0, 0, 3], "rotate": {"axis": [0, 0, 1], "degrees": 30},
       "scale": 2,
       "child": {"type": "instance", "master": "lamp"}},
      {"type": "quad", "material": "m", "corner": [-5, -5, 0], "edge_u": [10, 0, 0],
       "edge_v": [0, 10, 0]}]}
  })");
}

std::string error_of(const std::string& text) {
  try {
    scenes::parse_scene_json(text, "test.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// The message is one line: "test.json: PATH: PROBLEM...".
void expect_error(const json& scene, const std::string& path, const std::string& problem) {
  const std::string message = error_of(scene.dump());
  EXPECT_EQ(message.rfind("test.json: " + path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SceneFile, ValidSceneLoadsAndInstantiates) {
  const scenes::SceneDescription d = scenes::parse_scene_json(valid_scene().dump(), "test.json");
  const renderer::Scene scene = scenes::instantiate_scene(d);
  EXPECT_EQ(scene.lights.light_count, 1u);
  const std::vector<lev::Light> lights = lev::flatten_lights(scene.lights);
  ASSERT_EQ(lights.size(), 1u);
  EXPECT_FLOAT_EQ(lights[0].position.z, 3.0f);
  EXPECT_FLOAT_EQ(lights[0].intensity.x, 4.0f);  // scale 2: intensity times 4 (thesis 4.2.2)
  EXPECT_EQ(scene.materials.size(), 1u);
  EXPECT_FLOAT_EQ(scene.materials[0].kd, 0.5f);
}

TEST(SceneFile, UnknownKeys) {
  json s = valid_scene();
  s["colour"] = 1;
  expect_error(s, "/colour", "unknown key");
  s = valid_scene();
  s["camera"]["zoom"] = 2;
  expect_error(s, "/camera/zoom", "unknown key");
  s = valid_scene();
  s["root"]["children"][1]["radius"] = 2;
  expect_error(s, "/root/children/1/radius", "unknown key");
}

TEST(SceneFile, WrongTypes) {
  json s = valid_scene();
  s["camera"]["position"] = "here";
  expect_error(s, "/camera/position", "must be an array of 3 numbers (\"here\")");
  s = valid_scene();
  s["materials"][0]["kd"] = "high";
  expect_error(s, "/materials/0/kd", "must be a number");
  s = valid_scene();
  s["root"]["children"] = json::object();
  expect_error(s, "/root/children", "must be an array");
  s = valid_scene();
  s["root"]["children"][0]["child"]["master"] = 3;
  expect_error(s, "/root/children/0/child/master", "must be a string");
  s = valid_scene();
  s["root"]["children"][1]["type"] = "plane";
  expect_error(s, "/root/children/1/type", "unknown node type");
}

TEST(SceneFile, MissingFields) {
  json s = valid_scene();
  s.erase("camera");
  expect_error(s, "/camera", "missing");
  s = valid_scene();
  s["root"]["children"][1].erase("edge_v");
  expect_error(s, "/root/children/1/edge_v", "missing");
  s = valid_scene();
  s["masters"][0]["node"]["children"][0].erase("material");
  expect_error(s, "/masters/0/node/children/0/material", "missing");
}

TEST(SceneFile, NegativeNumbers) {
  json s = valid_scene();
  s["materials"][0]["kd"] = -1;
  expect_error(s, "/materials/0/kd", "must be >= 0 (-1)");
  s = valid_scene();
  s["masters"][0]["node"]["children"][0]["radius"] = -0.2;
  expect_error(s, "/masters/0/node/children/0/radius", "must be >= 0 (-0.2)");
  s = valid_scene();
  s["masters"][0]["node"]["children"][1]["intensity"] = {-1, 1, 1};
  expect_error(s, "/masters/0/node/children/1/intensity", ">= 0");
}

TEST(SceneFile, NonFiniteNumbers) {
  json s = valid_scene();
  s["masters"][0]["node"]["children"][0]["radius"] = 1e39;  // finite as a double, not as a float
  expect_error(s, "/masters/0/node/children/0/radius", "must be finite as a 32-bit float");
  std::string text = valid_scene().dump();
  text.replace(text.find("\"radius\":0.2"), 12, "\"radius\":1e999");
  const std::string message = error_of(text);
  EXPECT_EQ(message.rfind("test.json: /masters/0/node/children/0/radius: invalid JSON", 0), 0u)
      << message;
}

TEST(SceneFile, ZeroScale) {
  json s = valid_scene();
  s["root"]["children"][0]["scale"] = 0;
  expect_error(s, "/root/children/0/scale", "must be > 0 to be invertible (0)");
}

TEST(SceneFile, NonInvertibleScales) {
  json s = valid_scene();
  s["root"]["children"][0]["scale"] = 1e-30;
  expect_error(s, "/root/children/0/scale", "to stay invertible");
  // Each scale is fine, their product is not.
  s = valid_scene();
  json node = s["root"]["children"][0];
  for (int i = 0; i < 3; ++i) node = {{"type", "affine"}, {"scale", 1e-5}, {"child", node}};
  s["root"]["children"][0] = node;
  expect_error(s, "/root", "nested scales multiply to outside");
  s = valid_scene();
  s["root"]["children"][0]["rotate"]["axis"] = {0, 0, 0};
  expect_error(s, "/root/children/0/rotate/axis", "must not be zero");
}

TEST(SceneFile, UndefinedMastersAndMaterials) {
  json s = valid_scene();
  s["root"]["children"][0]["child"]["master"] = "lamps";
  expect_error(s, "/root/children/0/child/master", "no master named 'lamps'");
  s = valid_scene();
  s["root"]["children"][1]["material"] = "gold";
  expect_error(s, "/root/children/1/material", "no material named 'gold'");
  s = valid_scene();
  s["masters"].push_back(s["masters"][0]);
  expect_error(s, "/masters/1/name", "already defined");
}

TEST(SceneFile, InstanceCycles) {
  json s = valid_scene();
  s["masters"][0]["node"]["children"].push_back({{"type", "instance"}, {"master", "lamp"}});
  expect_error(s, "/masters/0/node/children/2/master", "instance cycle: 'lamp' -> 'lamp'");
  // Indirect: a -> b -> c -> a, defined in any order.
  s = valid_scene();
  s["masters"].push_back({{"name", "a"}, {"node", {{"type", "instance"}, {"master", "b"}}}});
  s["masters"].push_back(
      {{"name", "c"},
       {"node", {{"type", "affine"}, {"child", {{"type", "instance"}, {"master", "a"}}}}}});
  s["masters"].push_back({{"name", "b"}, {"node", {{"type", "instance"}, {"master", "c"}}}});
  expect_error(s, "/masters/2/node/child/master", "instance cycle: 'a' -> 'b' -> 'c' -> 'a'");
}

TEST(SceneFile, AbsurdSizes) {
  // Ten masters each instancing the previous ten times: the eighth (masters/8) has 10^8 lights.
  json s = valid_scene();
  for (int k = 1; k <= 10; ++k) {
    json children = json::array();
    for (int i = 0; i < 10; ++i) {
      children.push_back(
          {{"type", "affine"},
           {"translate", {i, 0, 0}},
           {"child",
            {{"type", "instance"}, {"master", k == 1 ? "lamp" : "x" + std::to_string(k - 1)}}}});
    }
    s["masters"].push_back(
        {{"name", "x" + std::to_string(k)}, {"node", {{"type", "union"}, {"children", children}}}});
  }
  s["root"]["children"][0]["child"]["master"] = "x10";
  expect_error(s, "/masters/8", "expands to more than 16777216 lights");
  // A chain of masters deeper than the instancing limit.
  s = valid_scene();
  for (int k = 1; k <= 70; ++k) {
    s["masters"].push_back(
        {{"name", "c" + std::to_string(k)},
         {"node",
          {{"type", "instance"}, {"master", k == 1 ? "lamp" : "c" + std::to_string(k - 1)}}}});
  }
  expect_error(s, "/masters/65", "instances nested more than 64 masters deep");
  s = valid_scene();
  s["root"]["children"][1]["corner"] = {1e9, 0, 0};
  expect_error(s, "/root/children/1/corner", "coordinate magnitude above");
  s = valid_scene();
  s["root"]["children"].push_back({{"type", "cylinder"},
                                   {"material", "m"},
                                   {"a", {0, 0, 0}},
                                   {"b", {0, 0, 1}},
                                   {"radius", 1},
                                   {"segments", 1000000}});
  expect_error(s, "/root/children/2/segments", "must be in [3, 1024]");
}

TEST(SceneFile, DeepNestingFailsCleanly) {
  // 10,000 nested affine nodes: refused while parsing, long before any recursion.
  std::string text =
      R"({"levrt_scene": 1, "camera": {"position": [0, -10, 5], "target": [0, 0, 0]}, "root": )";
  for (int i = 0; i < 10000; ++i) text += R"({"type": "affine", "child": )";
  text += R"({"type": "point_light", "intensity": [1, 1, 1]})";
  text += std::string(10000, '}') + "}";
  const std::string message = error_of(text);
  EXPECT_EQ(message.rfind("test.json: /root/child/child/", 0), 0u) << message.substr(0, 200);
  EXPECT_NE(message.find("JSON nested deeper than 256 levels"), std::string::npos)
      << message.substr(0, 300);
  EXPECT_LT(message.size(), 400u);
  // Arrays alone nest as deep.
  const std::string arrays = std::string(10000, '[') + std::string(10000, ']');
  EXPECT_NE(error_of(arrays).find("JSON nested deeper than 256 levels"), std::string::npos);
  // Nesting within the JSON limit but beyond the node limit.
  json node = {{"type", "point_light"}, {"intensity", {1, 1, 1}}};
  for (int i = 0; i < 150; ++i) node = {{"type", "affine"}, {"child", node}};
  json s = valid_scene();
  s["root"] = node;
  EXPECT_NE(error_of(s.dump()).find("nodes nested deeper than 100"), std::string::npos);
}

TEST(SceneFile, SyntaxErrorsNameTheLineAndPath) {
  std::string message =
      error_of("{\n  \"levrt_scene\": 1,\n  \"camera\": {\"position\": [0, 0,, 1]}\n}");
  EXPECT_EQ(message.rfind("test.json: /camera/position/2: invalid JSON at line 3", 0), 0u)
      << message;
  message = error_of(R"({"levrt_scene": 1, "levrt_scene": 1})");
  EXPECT_EQ(message.rfind("test.json: /levrt_scene: duplicate key", 0), 0u) << message;
  json s = valid_scene();
  s["levrt_scene"] = 2;
  expect_error(s, "/levrt_scene", "must be 1");
}

class SceneFileOnDisk : public ::testing::Test {
 protected:
  levrt_test::TempDir temp_{"levrt_scene_file_test_"};
  const std::filesystem::path& dir_ = temp_.path();
};

TEST_F(SceneFileOnDisk, HugeFileIsRefusedBeforeReading) {
  const std::string path = (dir_ / "huge.json").string();
  { std::ofstream(path) << "{"; }
  std::filesystem::resize_file(path, 100u << 20);  // sparse: 100 MB without writing them
  try {
    scenes::load_scene_file(path);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("more than the 64 MiB a scene file may have"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(scenes::load_scene_file((dir_ / "missing.json").string()), std::invalid_argument);
  EXPECT_THROW(scenes::load_scene_file(dir_.string()), std::invalid_argument);
}

TEST_F(SceneFileOnDisk, NameDefaultsToTheFileStem) {
  const std::string path = (dir_ / "lamp.json").string();
  { std::ofstream(path) << valid_scene().dump(); }
  EXPECT_EQ(scenes::load_scene_file(path).name, "lamp");
}

TEST(SceneFile, FlatListOfLightsGetsTheAutomaticHierarchy) {
  json s = valid_scene();
  json lights = json::array();
  for (int i = 0; i < 4000; ++i) {
    lights.push_back({{"type", "affine"},
                      {"translate", {(i % 80) * 3.0, (i / 80) * 3.0, 2.5}},
                      {"child", {{"type", "point_light"}, {"intensity", {0.5, 0.5, 0.5}}}}});
  }
  s["masters"] = json::array();
  s["root"] = {{"type", "union"}, {"children", lights}};
  renderer::Scene scene =
      scenes::instantiate_scene(scenes::parse_scene_json(s.dump(), "flat.json"));
  EXPECT_EQ(scene.lights.light_count, 4000u);
  std::size_t volumes = 0;
  for (const lev::HierarchyNode& n : scene.lights.nodes)
    volumes += n.kind == lev::NodeKind::extent_volume ? 1 : 0;
  EXPECT_GT(volumes, 1000u);  // a 4-wide BVH over 4000 lights
  const lev::ExtentVolumes extent_volumes = lev::fit_extent_volumes(scene.lights, 0.01f);
  lev::WalkScratch scratch;
  std::vector<lev::Light> found;
  lev::WalkCounters counters;
  const glm::vec3 p(100.0f, 60.0f, 0.0f);
  lev::find_important_lights(scene.lights, extent_volumes, 0.01f, p, scratch, found, counters);
  EXPECT_EQ(found.size(),
            lev::important_lights_brute_force(lev::flatten_lights(scene.lights), p, 0.01f).size());
  EXPECT_LT(counters.nodes_visited, 400u);
}

// The one escaping of quoted user text: C0 controls as before, and now what was printed raw: a
// right-to-left override (a name showing "gnp.exe" as "exe.png"), the other bidirectional and
// invisible format characters, C1 controls (U+009B is CSI to some terminals) and bytes of no
// UTF-8 character. Other characters stay, and escaping twice changes nothing.
TEST(SceneFile, EscapingShowsControlsOverridesAndStrayBytesAsEscapes) {
  using scenes::escape_control_characters;
  EXPECT_EQ(escape_control_characters("a\nb\x1b[2J"), "a\\nb\\x1b[2J");
  EXPECT_EQ(escape_control_characters("evil\u202Egnp.json"), "evil\\u202egnp.json");
  for (const char* format :
       {"\u061C", "\u200B", "\u200E", "\u200F", "\u2028", "\u2029", "\u202A", "\u202B", "\u202C",
        "\u202D", "\u2066", "\u2067", "\u2068", "\u2069", "\u2060", "\uFEFF"}) {
    const std::string escaped = escape_control_characters(format);
    EXPECT_EQ(escaped.rfind("\\u", 0), 0u) << escaped;
    EXPECT_EQ(escaped.size(), 6u) << escaped;
  }
  EXPECT_EQ(escape_control_characters("\xc2\x9b"
                                      "31m"),
            "\\u009b31m");
  EXPECT_EQ(escape_control_characters("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(escape_control_characters("\xe2\x80"), "\\xe2\\x80");           // a character cut short
  EXPECT_EQ(escape_control_characters("\xc0\xaf"), "\\xc0\\xaf");           // an overlong '/'
  EXPECT_EQ(escape_control_characters("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  const std::string kept = "caf\u00e9 \u5149 \U0001F4A1 \u00c5ngstr\u00f6m";
  EXPECT_EQ(escape_control_characters(kept), kept);
  for (const std::string& text : {std::string("x\u202Ey\n\xff"), std::string("\xc2\x85\t")}) {
    const std::string once = escape_control_characters(text);
    EXPECT_EQ(escape_control_characters(once), once) << once;
  }
}

}  // namespace
