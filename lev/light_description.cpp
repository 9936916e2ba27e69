#include "lev/light_description.h"

#include <utility>

namespace lev {

const char* node_kind_name(NodeKind kind) {
  switch (kind) {
    case NodeKind::point_light:
      return "point_light";
    case NodeKind::spot_light:
      return "spot_light";
    case NodeKind::affine:
      return "affine";
    case NodeKind::extent_volume:
      return "extent_volume";
    case NodeKind::set_union:
      return "union";
    case NodeKind::instance:
      return "instance";
    case NodeKind::master:
      return "master";
  }
  return "unknown";
}

LightDescriptionNode light_node(const Light& light) {
  LightDescriptionNode n;
  n.kind = light.kind == LightKind::point ? NodeKind::point_light : NodeKind::spot_light;
  n.light = light;
  return n;
}

LightDescriptionNode affine_node(const Similarity& xf, LightDescriptionNode child) {
  LightDescriptionNode n;
  n.kind = NodeKind::affine;
  n.transform = xf;
  n.children.push_back(std::move(child));
  return n;
}

LightDescriptionNode extent_volume_node(LightDescriptionNode child) {
  LightDescriptionNode n;
  n.kind = NodeKind::extent_volume;
  n.children.push_back(std::move(child));
  return n;
}

LightDescriptionNode union_node(std::vector<LightDescriptionNode> children) {
  LightDescriptionNode n;
  n.kind = NodeKind::set_union;
  n.children = std::move(children);
  return n;
}

LightDescriptionNode instance_node(std::uint32_t master) {
  LightDescriptionNode n;
  n.kind = NodeKind::instance;
  n.master = master;
  return n;
}

}  // namespace lev
