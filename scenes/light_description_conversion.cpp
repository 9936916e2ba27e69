#include "scenes/light_description_conversion.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "lev/hierarchy_cursor.h"
#include "lev/light_bvh.h"

namespace scenes {
namespace {

class LightDescriptionBuilder {
 public:
  // root: the scene's root, or its stand-in in render space.
  LightDescriptionBuilder(const SceneDescription& scene, const SceneNode& root,
                          const SceneAnalysis& analysis)
      : light_master_(scene.masters.size(), kNone) {
    for (std::uint32_t m : analysis.order()) {
      if (analysis.master(m).lights == 0) continue;
      std::optional<lev::LightDescriptionNode> node = convert(scene.masters[m].node);
      light_master_[m] = static_cast<std::uint32_t>(tree_.masters.size());
      tree_.masters.push_back(node ? hierarchy(std::move(*node)) : lev::union_node({}));
      master_lights_.push_back(lev::subtree_lights(tree_.masters.back(), master_lights_));
      tree_.master_names.push_back(scene.masters[m].name);
    }
    std::optional<lev::LightDescriptionNode> lights = convert(root);
    tree_.root = lights ? hierarchy(std::move(*lights)) : lev::union_node({});
  }

  lev::LightDescription take() { return std::move(tree_); }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  // The light part of a subtree, or nothing when it holds no light. Outside its masters a
  // subtree comes out as its atoms, the lights and the placed instances: a transform is folded
  // into the light below it (thesis 4.2.2: transforms give a light its place, direction and
  // intensity), so a light costs one node, and handed down to each atom of a union below it; a
  // union of unions is one union. A union has no box to cull with, so this loses no structure the
  // walk could use, and hierarchy() then builds the one it needs.
  std::optional<lev::LightDescriptionNode> convert(const SceneNode& node) const {
    if (const auto* a = std::get_if<Affine>(&node.data)) {
      std::optional<lev::LightDescriptionNode> child = convert(node.children[0]);
      if (!child) return std::nullopt;
      return place(affine_similarity(*a), std::move(*child));
    }
    if (std::holds_alternative<Union>(node.data)) {
      std::vector<lev::LightDescriptionNode> atoms;
      for (const SceneNode& c : node.children) {
        std::optional<lev::LightDescriptionNode> n = convert(c);
        if (!n) continue;
        if (lev::node_role(n->kind) != lev::NodeRole::group) {
          atoms.push_back(std::move(*n));
          continue;
        }
        for (lev::LightDescriptionNode& atom : n->children) atoms.push_back(std::move(atom));
      }
      if (atoms.empty()) return std::nullopt;
      if (atoms.size() == 1) return std::move(atoms[0]);
      return lev::union_node(std::move(atoms));
    }
    if (const auto* in = std::get_if<Instance>(&node.data)) {
      if (light_master_[in->master] == kNone) return std::nullopt;
      return lev::instance_node(light_master_[in->master]);
    }
    if (const auto* p = std::get_if<PointLightSource>(&node.data)) {
      lev::Light light = lev::make_point_light(glm::vec3(0.0f), p->intensity);
      light.range = p->range;
      return lev::light_node(light);
    }
    if (const auto* s = std::get_if<SpotLightSource>(&node.data)) {
      const auto radians = [](float degrees) {
        return static_cast<float>(static_cast<double>(degrees) * M_PI / 180.0);
      };
      const glm::vec3 axis(0.0f, 0.0f, -1.0f);
      lev::Light light = s->inner_cone_degrees < 0.0f
                             ? lev::make_spot_light(glm::vec3(0.0f), axis, s->intensity,
                                                    radians(s->cone_degrees), s->dropoff)
                             : lev::make_smooth_spot_light(glm::vec3(0.0f), axis, s->intensity,
                                                           radians(s->inner_cone_degrees),
                                                           radians(s->cone_degrees));
      light.range = s->range;
      return lev::light_node(light);
    }
    return std::nullopt;
  }

  // An atom or a union of atoms seen through xf.
  static lev::LightDescriptionNode place(const lev::Similarity& xf,
                                         lev::LightDescriptionNode node) {
    if (lev::is_identity(xf)) return node;
    switch (lev::node_role(node.kind)) {
      case lev::NodeRole::light:
        return lev::light_node(lev::transform_light(node.light, xf));
      case lev::NodeRole::transform:
        return lev::affine_node(lev::compose(xf, node.transform), std::move(node.children[0]));
      case lev::NodeRole::group:
        for (lev::LightDescriptionNode& atom : node.children) atom = place(xf, std::move(atom));
        return node;
      case lev::NodeRole::reference:
      case lev::NodeRole::bounded:
        break;
    }
    return lev::affine_node(xf, std::move(node));
  }

  // A master's or the root's light part as the walk gets it: more than kMaxUnstructuredLights
  // atoms (bare lights, instances of a lamp placed thousands of times, or both, whatever unions
  // and transforms they came in) get the automatic hierarchy over their lights (positions,
  // intensities and spot cones), instances kept as instances; fewer stay a union.
  lev::LightDescriptionNode hierarchy(lev::LightDescriptionNode node) const {
    if (lev::node_role(node.kind) != lev::NodeRole::group ||
        node.children.size() <= kMaxUnstructuredLights)
      return node;
    std::vector<lev::BvhItem> items;
    items.reserve(node.children.size());
    for (lev::LightDescriptionNode& atom : node.children) {
      const lev::SubtreeLights lights = lev::subtree_lights(atom, master_lights_);
      items.push_back({std::move(atom), lights});
    }
    return lev::build_bvh(std::move(items));
  }

  std::vector<std::uint32_t> light_master_;
  std::vector<lev::SubtreeLights> master_lights_;  // parallel to tree_.masters
  lev::LightDescription tree_;
};

}  // namespace

lev::LightDescription convert_lights(const SceneDescription& scene, const SceneNode& root,
                                     const SceneAnalysis& analysis) {
  return LightDescriptionBuilder(scene, root, analysis).take();
}

}  // namespace scenes
