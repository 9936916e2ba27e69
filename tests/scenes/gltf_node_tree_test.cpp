// The node tree's shape (scenes/gltf_node_tree.h): a node listed under two parents, twice under
// one, twice in a scene or both as a root and as a child is refused naming it and both places,
// as is a loop of parents even outside the default scene; a forest of separate trees is read.
#include "scenes/gltf_node_tree.h"

#include <string>

#include <gtest/gtest.h>

#include "scenes/gltf_scene.h"
#include "tests/support/gltf_refusal.h"

namespace {

constexpr char kTreePath[] = "tree.gltf";

// Node 0 carries the one point light; `roots` lists the scene's nodes, `nodes` follow node 0.
std::string gltf_tree_with(const std::string& roots, const std::string& nodes) {
  return R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point"}]}},
    "scenes": [{"nodes": )" +
         roots + R"(}], "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}})" + nodes +
         "]}";
}

TEST(GltfNodeTree, ANodeReachableTwiceIsRefusedNamingIt) {
  const std::pair<std::string, std::string> cases[] = {
      {gltf_tree_with("[1, 2]", R"(, {"children": [0]}, {"children": [0]})"),
       "nodes[0]: a child of both nodes[1] and nodes[2] (a node has one parent)"},
      {gltf_tree_with("[1]", R"(, {"children": [0, 0]})"),
       "nodes[0]: listed twice in nodes[1].children"},
      {gltf_tree_with("[0, 0]", ""), "nodes[0]: listed twice in scenes[0].nodes"},
      {gltf_tree_with("[0, 1]", R"(, {"children": [0]})"),
       "nodes[0]: a root of scenes[0].nodes and a child of nodes[1] (reachable twice)"},
      // Outside the scene: nodes 1 and 2 are each other's parent.
      {gltf_tree_with("[0]", R"(, {"children": [2]}, {"children": [1]})"),
       "nodes[1]: cycle in the node tree"},
      {gltf_tree_with("[1]", R"(, {"children": [1]})"), "nodes[1]: cycle in the node tree"},
  };
  for (const auto& [text, problem] : cases)
    levrt_test::expect_gltf_refused(text, kTreePath, problem);
}

TEST(GltfNodeTree, SeparateTreesAreReadOnceEach) {
  const scenes::SceneDescription scene = scenes::parse_gltf_scene(
      gltf_tree_with("[1, 3]", R"(, {"children": [0, 2]}, {}, {"children": [4]}, {})"), kTreePath);
  EXPECT_EQ(scene.root.children.size(), 1u);  // the light, once
}

}  // namespace
