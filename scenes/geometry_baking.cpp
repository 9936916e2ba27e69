#include "scenes/geometry_baking.h"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "renderer/direction.h"
#include "renderer/shapes.h"

namespace scenes {
namespace {

// One prototype being filled: one mesh per material (fewer Embree geometries), spheres apart.
class PrototypeBuilder {
 public:
  explicit PrototypeBuilder(const SceneDescription& scene)
      : scene_(scene), mesh_of_material_(scene.materials.size(), -1) {}

  void add(const NodeData& data, const lev::Similarity& xf) {
    if (const auto* m = std::get_if<MeshShape>(&data)) {
      for (const renderer::TriangleMesh& part : scene_.meshes[m->mesh].parts)
        add_mesh_part(part, m->linear, xf);
      return;
    }
    renderer::TriangleMesh local;
    std::uint32_t material = 0;
    if (const auto* s = std::get_if<SphereShape>(&data)) {
      renderer::Sphere sphere;
      sphere.centre = lev::apply_point(xf, s->centre);
      sphere.radius = s->radius * xf.scale;
      sphere.material = s->material;
      prototype_.spheres.push_back(sphere);
      return;
    }
    if (const auto* b = std::get_if<BoxShape>(&data)) {
      material = b->material;
      renderer::add_box(local, b->lo, b->hi);
    } else if (const auto* c = std::get_if<CylinderShape>(&data)) {
      material = c->material;
      renderer::add_cylinder(local, c->a, c->b, c->radius, c->segments);
    } else if (const auto* q = std::get_if<QuadShape>(&data)) {
      material = q->material;
      renderer::add_quad(local, q->corner, q->edge_u, q->edge_v);
    } else {
      return;
    }
    renderer::TriangleMesh& mesh = mesh_for(material);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const bool identity = lev::is_identity(xf);
    for (std::size_t i = 0; i < local.positions.size(); ++i) {
      mesh.positions.push_back(identity ? local.positions[i]
                                        : lev::apply_point(xf, local.positions[i]));
      mesh.normals.push_back(identity ? local.normals[i]
                                      : lev::apply_direction(xf, local.normals[i]));
    }
    for (const glm::uvec3& t : local.triangles) mesh.triangles.push_back(t + glm::uvec3(base));
    if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.positions.size(), glm::vec2(0.0f));
  }

  bool empty() const { return prototype_.meshes.empty() && prototype_.spheres.empty(); }

  // Positions through linear then xf, normals through linear's inverse transpose; a mirroring
  // linear reverses the winding too, so the winding-derived geometric normal still agrees.
  void add_mesh_part(const renderer::TriangleMesh& part, const glm::mat3& linear,
                     const lev::Similarity& xf) {
    renderer::TriangleMesh& mesh = mesh_for(part.material);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const glm::mat3 normal_map = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    for (std::size_t i = 0; i < part.positions.size(); ++i) {
      mesh.positions.push_back(lev::apply_point(xf, linear * part.positions[i]));
      const glm::vec3 n = renderer::robust_normalize(normal_map * part.normals[i]);
      mesh.normals.push_back(lev::apply_direction(xf, n));
    }
    // A mesh has uvs for every vertex or none: vertices from parts without get (0, 0).
    if (!part.uvs.empty()) {
      mesh.uvs.resize(base, glm::vec2(0.0f));
      mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
    } else if (!mesh.uvs.empty()) {
      mesh.uvs.resize(mesh.positions.size(), glm::vec2(0.0f));
    }
    for (const glm::uvec3& t : part.triangles) {
      mesh.triangles.push_back(mirrored ? glm::uvec3(t.x, t.z, t.y) + glm::uvec3(base)
                                        : t + glm::uvec3(base));
    }
  }
  renderer::Prototype take() { return std::move(prototype_); }

 private:
  renderer::TriangleMesh& mesh_for(std::uint32_t material) {
    std::int64_t& index = mesh_of_material_[material];
    if (index < 0) {
      index = static_cast<std::int64_t>(prototype_.meshes.size());
      prototype_.meshes.emplace_back();
      prototype_.meshes.back().material = material;
    }
    return prototype_.meshes[static_cast<std::size_t>(index)];
  }

  const SceneDescription& scene_;
  renderer::Prototype prototype_;
  std::vector<std::int64_t> mesh_of_material_;
};

class GeometryBuilder {
 public:
  // root: the scene's root, or its stand-in in render space.
  GeometryBuilder(const SceneDescription& scene, const SceneNode& root,
                  const SceneAnalysis& analysis)
      : scene_(scene),
        analysis_(analysis),
        baked_(scene.masters.size(), kNone),
        flattened_(scene.masters.size()),
        flattened_done_(scene.masters.size(), false) {
    place(flatten(root), lev::Similarity{});
  }

  renderer::Geometry take() { return std::move(geometry_); }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  struct Site {
    std::uint32_t master = 0;
    lev::Similarity xf;
  };
  // An unbaked master (or the root): its own primitives as one prototype, and where it places
  // the masters it instances.
  struct Flattened {
    std::uint32_t prototype = kNone;
    std::vector<Site> sites;
  };

  void collect(const SceneNode& node, const lev::Similarity& xf, PrototypeBuilder& own,
               std::vector<Site>* sites) {
    if (const auto* a = std::get_if<Affine>(&node.data)) {
      collect(node.children[0], lev::compose(xf, affine_similarity(*a)), own, sites);
    } else if (std::holds_alternative<Union>(node.data)) {
      for (const SceneNode& c : node.children) collect(c, xf, own, sites);
    } else if (const auto* in = std::get_if<Instance>(&node.data)) {
      if (analysis_.master(in->master).triangles == 0) return;
      if (sites) {
        sites->push_back({in->master, xf});
      } else {
        collect(scene_.masters[in->master].node, xf, own, nullptr);
      }
    } else {
      own.add(node.data, xf);
    }
  }

  std::uint32_t add_prototype(PrototypeBuilder& builder) {
    geometry_.prototypes.push_back(builder.take());
    return static_cast<std::uint32_t>(geometry_.prototypes.size() - 1);
  }

  Flattened flatten(const SceneNode& node) {
    Flattened f;
    PrototypeBuilder own(scene_);
    collect(node, lev::Similarity{}, own, &f.sites);
    if (!own.empty()) f.prototype = add_prototype(own);
    return f;
  }

  std::uint32_t baked_prototype(std::uint32_t m) {
    if (baked_[m] == kNone) {
      PrototypeBuilder all(scene_);
      collect(scene_.masters[m].node, lev::Similarity{}, all, nullptr);
      baked_[m] = add_prototype(all);
    }
    return baked_[m];
  }

  const Flattened& flattened(std::uint32_t m) {
    if (!flattened_done_[m]) {
      flattened_[m] = flatten(scene_.masters[m].node);
      flattened_done_[m] = true;
    }
    return flattened_[m];
  }

  // Recursion depth is bounded by kMaxInstanceDepth.
  void place(const Flattened& f, const lev::Similarity& world) {
    if (f.prototype != kNone) geometry_.instances.push_back({f.prototype, world});
    for (const Site& site : f.sites) {
      const lev::Similarity xf = lev::compose(world, site.xf);
      if (analysis_.baked(site.master)) {
        geometry_.instances.push_back({baked_prototype(site.master), xf});
      } else {
        place(flattened(site.master), xf);
      }
    }
  }

  const SceneDescription& scene_;
  const SceneAnalysis& analysis_;
  std::vector<std::uint32_t> baked_;
  std::vector<Flattened> flattened_;
  std::vector<bool> flattened_done_;
  renderer::Geometry geometry_;
};

}  // namespace

renderer::Geometry bake_geometry(const SceneDescription& scene, const SceneNode& root,
                                 const SceneAnalysis& analysis) {
  return GeometryBuilder(scene, root, analysis).take();
}

}  // namespace scenes
