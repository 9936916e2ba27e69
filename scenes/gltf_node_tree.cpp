#include "scenes/gltf_node_tree.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace scenes {
namespace {

constexpr int kNoParent = -1;

std::string node_name(std::size_t index) {
  return "nodes[" + std::to_string(index) + "]";
}

[[noreturn]] void fail(const std::string& path, const std::string& where,
                       const std::string& problem) {
  throw std::invalid_argument(path + ": " + where + ": " + problem);
}

// Each node's one parent, refusing a node listed twice (under two parents or twice under one).
std::vector<int> parents_of(const tinygltf::Model& model, const std::string& path) {
  std::vector<int> parent(model.nodes.size(), kNoParent);
  for (std::size_t p = 0; p < model.nodes.size(); ++p) {
    for (const int child : model.nodes[p].children) {
      if (child < 0 || static_cast<std::size_t>(child) >= model.nodes.size())
        fail(path, node_name(p) + ".children", std::to_string(child));
      int& slot = parent[static_cast<std::size_t>(child)];
      if (slot == static_cast<int>(p))
        fail(path, node_name(static_cast<std::size_t>(child)),
             "listed twice in " + node_name(p) + ".children (a node is reachable once)");
      if (slot != kNoParent) {
        fail(path, node_name(static_cast<std::size_t>(child)),
             "a child of both " + node_name(static_cast<std::size_t>(slot)) + " and " +
                 node_name(p) + " (a node has one parent)");
      }
      slot = static_cast<int>(p);
    }
  }
  return parent;
}

// With one parent each, the nodes form trees unless a chain of parents loops: each chain is
// walked once, marking the nodes on it.
void refuse_loops(const std::vector<int>& parent, const std::string& path) {
  enum : unsigned char { kUnseen, kOnChain, kDone };
  std::vector<unsigned char> state(parent.size(), kUnseen);
  std::vector<std::size_t> chain;
  for (std::size_t start = 0; start < parent.size(); ++start) {
    chain.clear();
    int at = static_cast<int>(start);
    while (at != kNoParent && state[static_cast<std::size_t>(at)] == kUnseen) {
      state[static_cast<std::size_t>(at)] = kOnChain;
      chain.push_back(static_cast<std::size_t>(at));
      at = parent[static_cast<std::size_t>(at)];
    }
    if (at != kNoParent && state[static_cast<std::size_t>(at)] == kOnChain)
      fail(path, node_name(static_cast<std::size_t>(at)), "cycle in the node tree");
    for (const std::size_t node : chain) state[node] = kDone;
  }
}

}  // namespace

void check_gltf_node_tree(const tinygltf::Model& model, const std::string& path) {
  const std::vector<int> parent = parents_of(model, path);
  refuse_loops(parent, path);
  for (std::size_t s = 0; s < model.scenes.size(); ++s) {
    const std::string scene = "scenes[" + std::to_string(s) + "].nodes";
    std::vector<bool> listed(model.nodes.size(), false);
    for (const int root : model.scenes[s].nodes) {
      if (root < 0 || static_cast<std::size_t>(root) >= model.nodes.size())
        fail(path, scene, std::to_string(root));
      const auto r = static_cast<std::size_t>(root);
      if (listed[r]) fail(path, node_name(r), "listed twice in " + scene);
      listed[r] = true;
      if (parent[r] != kNoParent) {
        fail(path, node_name(r),
             "a root of " + scene + " and a child of " +
                 node_name(static_cast<std::size_t>(parent[r])) + " (reachable twice)");
      }
    }
  }
}

}  // namespace scenes
