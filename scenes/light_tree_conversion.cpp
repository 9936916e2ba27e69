#include "scenes/light_tree_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "lev/light_bvh.h"

namespace scenes {
namespace {

bool is_light_leaf(const lev::LightTreeNode& n) {
  return n.kind == lev::NodeKind::point_light || n.kind == lev::NodeKind::spot_light;
}

class LightTreeBuilder {
 public:
  // root: the scene's root, or its stand-in in render space.
  LightTreeBuilder(const SceneDescription& scene, const SceneNode& root, const SceneAnalysis& analysis)
      : light_master_(scene.masters.size(), kNone) {
    for (std::uint32_t m : analysis.order()) {
      if (analysis.master(m).lights == 0) continue;
      std::optional<lev::LightTreeNode> node = convert(scene.masters[m].node);
      light_master_[m] = static_cast<std::uint32_t>(tree_.masters.size());
      tree_.masters.push_back(node ? std::move(*node) : lev::union_node({}));
      tree_.master_names.push_back(scene.masters[m].name);
    }
    std::optional<lev::LightTreeNode> lights = convert(root);
    tree_.root = lights ? std::move(*lights) : lev::union_node({});
  }

  lev::LightTree take() { return std::move(tree_); }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  // The light part of a subtree, or nothing when it holds no light. A transform right above a
  // light is folded into the light (thesis 4.2.2: transforms give a light its place, direction
  // and intensity), so a light costs one node.
  std::optional<lev::LightTreeNode> convert(const SceneNode& node) const {
    if (const auto* a = std::get_if<Affine>(&node.data)) {
      std::optional<lev::LightTreeNode> child = convert(node.children[0]);
      if (!child) return std::nullopt;
      const lev::Similarity xf = affine_similarity(*a);
      if (lev::is_identity(xf)) return child;
      if (is_light_leaf(*child)) return lev::light_node(lev::transform_light(child->light, xf));
      if (child->kind == lev::NodeKind::affine) {
        return lev::affine_node(lev::compose(xf, child->transform), std::move(child->children[0]));
      }
      return lev::affine_node(xf, std::move(*child));
    }
    if (std::holds_alternative<Union>(node.data)) {
      std::vector<lev::LightTreeNode> children;
      for (const SceneNode& c : node.children) {
        if (std::optional<lev::LightTreeNode> n = convert(c)) children.push_back(std::move(*n));
      }
      gather_bare_lights(children);
      if (children.empty()) return std::nullopt;
      if (children.size() == 1) return std::move(children[0]);
      return lev::union_node(std::move(children));
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

  // Many bare lights side by side: replace them by an automatic hierarchy, placed where the first
  // of them was (the order of a union's children is the order lights are summed in).
  static void gather_bare_lights(std::vector<lev::LightTreeNode>& children) {
    const auto bare = static_cast<std::size_t>(std::count_if(children.begin(), children.end(), is_light_leaf));
    if (bare <= kMaxUnstructuredLights) return;
    std::vector<lev::Light> lights;
    std::vector<lev::LightTreeNode> kept;
    std::size_t bvh_at = 0;
    for (lev::LightTreeNode& c : children) {
      if (is_light_leaf(c)) {
        if (lights.empty()) bvh_at = kept.size();
        lights.push_back(c.light);
      } else {
        kept.push_back(std::move(c));
      }
    }
    kept.insert(kept.begin() + static_cast<std::ptrdiff_t>(bvh_at), lev::build_light_bvh(lights));
    children = std::move(kept);
  }

  std::vector<std::uint32_t> light_master_;
  lev::LightTree tree_;
};

}  // namespace

lev::LightTree convert_lights(const SceneDescription& scene, const SceneNode& root,
                              const SceneAnalysis& analysis) {
  return LightTreeBuilder(scene, root, analysis).take();
}

}  // namespace scenes
