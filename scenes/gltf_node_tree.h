// The shape glTF demands of its nodes, checked over the whole file before the scene is built: the
// nodes form disjoint trees, so a node is the child of at most one parent and listed once in its
// parent's children, a scene's root nodes are listed once and have no parent, and no chain of
// parents loops. Otherwise a node reachable twice would be drawn twice (a light listed under two
// parents doubled its light); each breach is one line "FILE: nodes[5]: ..." naming the node and
// the two places it is listed. Indices are inside their arrays already (gltf_schema.h).
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace scenes {

void check_gltf_node_tree(const tinygltf::Model& model, const std::string& path);

}  // namespace scenes
