// The description of a light hierarchy as a scene states it (thesis 4.2.2): a tree of point and
// spot lights under affine, extent-volume and union nodes, plus named masters that instance nodes
// refer to. Scenes and scene files build this; build_hierarchy flattens it for queries.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lev/light.h"
#include "lev/transform.h"

namespace lev {

enum class NodeKind : std::uint8_t {
  point_light,    // leaf
  spot_light,     // leaf
  affine,         // one child, seen through a similarity transform
  extent_volume,  // one child, culled when the query point is outside its extent volume
  set_union,      // any number of children
  instance,       // refers to a master
  master,         // root of a subtree stored once; carries its extent volume
};

const char* node_kind_name(NodeKind kind);

struct LightDescriptionNode {
  NodeKind kind = NodeKind::set_union;
  Light light;                                 // point_light, spot_light
  Similarity transform;                        // affine
  std::uint32_t master = 0;                    // instance: index into LightDescription::masters
  std::vector<LightDescriptionNode> children;  // affine, extent_volume: exactly one; set_union: any
};

struct LightDescription {
  // masters[i] may instance masters[j] only for j < i, so a master is complete before use and
  // no cycle can exist.
  std::vector<LightDescriptionNode> masters;
  std::vector<std::string> master_names;  // optional, parallel to masters (for files and errors)
  LightDescriptionNode root;
};

LightDescriptionNode light_node(const Light& light);
LightDescriptionNode affine_node(const Similarity& xf, LightDescriptionNode child);
LightDescriptionNode extent_volume_node(LightDescriptionNode child);
LightDescriptionNode union_node(std::vector<LightDescriptionNode> children);
LightDescriptionNode instance_node(std::uint32_t master);

}  // namespace lev
