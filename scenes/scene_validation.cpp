#include "scenes/scene_validation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "renderer/camera.h"
#include "renderer/denormal_mode.h"
#include "renderer/direction.h"

namespace scenes {
namespace {

std::uint64_t add_saturating(std::uint64_t a, std::uint64_t b) {
  return a > std::numeric_limits<std::uint64_t>::max() - b
             ? std::numeric_limits<std::uint64_t>::max()
             : a + b;
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string vec_text(const glm::vec3& v) {
  return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
}

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::invalid_argument(path + ": " + problem);
}

void check_finite(const std::string& path, float v, float max_abs) {
  if (!std::isfinite(v)) fail(path, "must be finite (" + number_text(v) + ")");
  if (std::abs(v) > max_abs)
    fail(path, "magnitude above " + number_text(max_abs) + " (" + number_text(v) + ")");
}

void check_point(const std::string& path, const glm::vec3& v) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i])) fail(path, "must be finite " + vec_text(v));
    if (std::abs(v[i]) > kMaxCoordinate) {
      fail(path, "coordinate magnitude above " + number_text(kMaxCoordinate) + " " + vec_text(v));
    }
  }
}

void check_non_negative(const std::string& path, float v, float max) {
  if (!std::isfinite(v)) fail(path, "must be finite (" + number_text(v) + ")");
  if (v < 0.0f) fail(path, "must be >= 0 (" + number_text(v) + ")");
  if (v > max) fail(path, "must be <= " + number_text(max) + " (" + number_text(v) + ")");
}

void check_positive(const std::string& path, float v, float max) {
  check_non_negative(path, v, max);
  if (!(v > 0.0f)) fail(path, "must be > 0 (" + number_text(v) + ")");
}

void check_colour(const std::string& path, const glm::vec3& c, float max) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(c[i]) || c[i] < 0.0f || c[i] > max) {
      fail(path, "channels must be finite, >= 0 and <= " + number_text(max) + " " + vec_text(c));
    }
  }
}

int triangles_of(const NodeData& data) {
  if (std::holds_alternative<SphereShape>(data)) return 1;
  if (std::holds_alternative<BoxShape>(data)) return 12;
  if (const auto* c = std::get_if<CylinderShape>(&data)) return 4 * c->segments;
  if (std::holds_alternative<QuadShape>(data)) return 2;
  return 0;
}

bool is_light(const NodeData& data) {
  return std::holds_alternative<PointLightSource>(data) ||
         std::holds_alternative<SpotLightSource>(data);
}

struct Edge {
  std::uint32_t master = 0;
  std::string path;
};

// Checks, master by master, every value, counts and the instance graph; orders the masters so
// each comes after everything it instances; sums what each master expands to.
class Analysis {
 public:
  explicit Analysis(const SceneDescription& scene) : scene_(scene) {
    if (scene.masters.size() > kMaxMasters) {
      fail("/masters", "more than " + std::to_string(kMaxMasters) + " masters (" +
                           std::to_string(scene.masters.size()) + ")");
    }
    if (scene.materials.size() > kMaxMaterials) {
      fail("/materials", "more than " + std::to_string(kMaxMaterials) + " materials (" +
                             std::to_string(scene.materials.size()) + ")");
    }
    check_header();
    check_meshes();
    edges_.resize(scene.masters.size());
    for (std::size_t m = 0; m < scene.masters.size(); ++m) {
      const std::string path = "/masters/" + std::to_string(m);
      if (scene.masters[m].name.empty()) fail(path + "/name", "must not be empty");
      for (std::size_t k = 0; k < m; ++k) {
        if (scene.masters[k].name == scene.masters[m].name) {
          fail(path + "/name",
               "a master of this name is already defined ('" + scene.masters[m].name + "')");
        }
      }
      check_node(scene.masters[m].node, path + "/node", 0, edges_[m]);
    }
    std::vector<Edge> root_edges;
    check_node(scene.root, "/root", 0, root_edges);
    order_masters();
    totals_.resize(scene.masters.size());
    for (std::uint32_t m : order_) {
      totals_[m] = sum_node(scene.masters[m].node);
      check_totals(totals_[m], "/masters/" + std::to_string(m));
    }
    root_ = sum_node(scene.root);
    check_totals(root_, "/root");
    check_prototype_triangles(root_edges);
  }

  SceneAnalysis result() && { return {std::move(order_), std::move(totals_)}; }
  bool baked(std::uint32_t m) const { return totals_[m].triangles <= kBakeTriangleBudget; }
  std::uint64_t placements_unbaked(const SubtreeTotals& t) const {
    return add_saturating(t.site_placements, t.direct_triangles > 0 ? 1 : 0);
  }

 private:
  void check_header() {
    const renderer::Camera& c = scene_.camera;
    check_point("/camera/position", c.position);
    check_point("/camera/target", c.target);
    check_point("/camera/up", c.up);
    // The frame is computed as the render threads compute it, in their float mode (flush to
    // zero): a camera that degenerates there (a target 1e-40 from the position, up 1e-39) is
    // refused here rather than casting NaN rays.
    renderer::CameraBasis basis;
    glm::vec3 forward(0.0f), unit_up(0.0f);
    {
      renderer::DenormalModeGuard render_float_mode;
      basis = renderer::camera_basis(c);
      forward = renderer::robust_normalize(c.target - c.position);
      unit_up = renderer::robust_normalize(c.up);
    }
    if (forward == glm::vec3(0.0f))
      fail("/camera/target", "must differ from the position " + vec_text(c.target));
    if (basis.right == glm::vec3(0.0f) || !(glm::length(glm::cross(forward, unit_up)) > 1e-6f)) {
      fail("/camera/up", "must not be zero or parallel to the view direction " + vec_text(c.up));
    }
    if (!std::isfinite(c.vertical_fov_deg) || !(c.vertical_fov_deg > 0.0f) ||
        !(c.vertical_fov_deg < 180.0f)) {
      fail("/camera/fov_degrees", "must be in (0, 180) (" + number_text(c.vertical_fov_deg) + ")");
    }
    // At most kMaxCoordinate, like any length: rays start up to the half height times the aspect
    // ratio from the camera, and Embree refuses (asserts on) origins past about 1.8e18.
    if (!std::isfinite(c.orthographic_half_height) || !(c.orthographic_half_height >= 0.0f) ||
        c.orthographic_half_height > kMaxCoordinate) {
      fail("/camera/orthographic_half_height", "must be in [0, " + number_text(kMaxCoordinate) +
                                                   "], 0 for a perspective camera (" +
                                                   number_text(c.orthographic_half_height) + ")");
    }
    check_colour("/ambient", scene_.ambient, 1e6f);
    check_colour("/background", scene_.background, 1e6f);
    if (scene_.level < 0) fail("/level", "must be >= 0 (" + std::to_string(scene_.level) + ")");
    for (std::size_t i = 0; i < scene_.directional_lights.size(); ++i) {
      const std::string path = "/directional_lights/" + std::to_string(i);
      const renderer::DirectionalLight& sun = scene_.directional_lights[i];
      check_colour(path + "/irradiance", sun.irradiance, kMaxIntensity);
      check_point(path + "/direction", sun.direction);
      if (!(std::abs(glm::length(sun.direction) - 1.0f) < 1e-4f)) {
        fail(path + "/direction", "must be a unit vector " + vec_text(sun.direction));
      }
    }
    for (std::size_t i = 0; i < scene_.materials.size(); ++i) {
      const std::string path = "/materials/" + std::to_string(i);
      const NamedMaterial& nm = scene_.materials[i];
      if (nm.name.empty()) fail(path + "/name", "must not be empty");
      for (std::size_t k = 0; k < i; ++k) {
        if (scene_.materials[k].name == nm.name) {
          fail(path + "/name", "a material of this name is already defined ('" + nm.name + "')");
        }
      }
      const renderer::Material& m = nm.material;
      check_colour(path + "/colour", m.colour, 1e3f);
      check_non_negative(path + "/ka", m.ka, 1e3f);
      check_non_negative(path + "/kd", m.kd, 1e3f);
      check_non_negative(path + "/ks", m.ks, 1e3f);
      check_non_negative(path + "/shininess", m.shininess, 1e6f);
      check_non_negative(path + "/kr", m.kr, 1e3f);
      check_non_negative(path + "/kt", m.kt, 1e3f);
      // Below 0.01 the refraction ratio's square overflows (1/ior^2), and a head-on ray of ior
      // 1e-30 computed inf * 0; [0.01, 100] is symmetric and holds every physical medium.
      if (!std::isfinite(m.ior) || m.ior < 0.01f || m.ior > 100.0f) {
        fail(path + "/ior", "must be in [0.01, 100] (" + number_text(m.ior) + ")");
      }
      if (m.colour_texture < -1 ||
          m.colour_texture >= static_cast<std::int64_t>(scene_.textures.size())) {
        fail(path + "/colour_texture",
             "no such texture (" + std::to_string(m.colour_texture) + ")");
      }
    }
  }

  // Each mesh once, however many nodes draw it; textures too.
  void check_meshes() {
    for (std::size_t t = 0; t < scene_.textures.size(); ++t) {
      const renderer::Texture& texture = scene_.textures[t];
      if (texture.width <= 0 || texture.height <= 0 ||
          texture.texels.size() !=
              static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height)) {
        fail("/textures/" + std::to_string(t), std::to_string(texture.texels.size()) +
                                                   " texels for " + std::to_string(texture.width) +
                                                   "x" + std::to_string(texture.height));
      }
    }
    for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
      const std::string path = "/meshes/" + std::to_string(m);
      std::uint64_t triangles = 0;
      for (std::size_t k = 0; k < scene_.meshes[m].parts.size(); ++k) {
        const std::string part_path = path + "/parts/" + std::to_string(k);
        const renderer::TriangleMesh& part = scene_.meshes[m].parts[k];
        check_material(part_path, part.material);
        if (part.normals.size() != part.positions.size()) {
          fail(part_path + "/normals", std::to_string(part.normals.size()) + " normals for " +
                                           std::to_string(part.positions.size()) + " positions");
        }
        if (!part.uvs.empty() && part.uvs.size() != part.positions.size()) {
          fail(part_path + "/uvs", std::to_string(part.uvs.size()) + " uvs for " +
                                       std::to_string(part.positions.size()) + " positions");
        }
        for (const glm::vec3& p : part.positions) check_point(part_path + "/positions", p);
        for (const glm::vec3& n : part.normals) check_point(part_path + "/normals", n);
        for (const glm::uvec3& t : part.triangles) {
          if (t.x >= part.positions.size() || t.y >= part.positions.size() ||
              t.z >= part.positions.size()) {
            fail(part_path + "/triangles",
                 "vertex index beyond the " + std::to_string(part.positions.size()) + " positions");
          }
        }
        triangles = add_saturating(triangles, part.triangles.size());
      }
      mesh_triangles_.push_back(triangles);
    }
  }

  void check_material(const std::string& path, std::uint32_t material) const {
    if (material >= scene_.materials.size()) {
      fail(path + "/material", "no such material (" + std::to_string(material) + ")");
    }
  }

  void check_node(const SceneNode& node, const std::string& path, int depth,
                  std::vector<Edge>& edges) {
    if (depth > kMaxNodeDepth)
      fail(path, "nodes nested deeper than " + std::to_string(kMaxNodeDepth));
    if (++node_count_ > kMaxSceneNodes)
      fail(path, "more than " + std::to_string(kMaxSceneNodes) + " nodes");
    const std::size_t expected_children = std::holds_alternative<Affine>(node.data) ? 1
                                          : std::holds_alternative<Union>(node.data)
                                              ? node.children.size()
                                              : 0;
    if (node.children.size() != expected_children) {
      fail(path, std::string(node_type_name(node.data)) + " node needs " +
                     std::to_string(expected_children) + " children, has " +
                     std::to_string(node.children.size()));
    }
    if (const auto* a = std::get_if<Affine>(&node.data)) {
      check_point(path + "/translate", a->translate);
      check_point(path + "/rotate/axis", a->rotate_axis);
      check_finite(path + "/rotate/degrees", a->rotate_degrees, 1e6f);
      if (!(glm::length(a->rotate_axis) > 0.0f))
        fail(path + "/rotate/axis", "must not be zero " + vec_text(a->rotate_axis));
      if (!std::isfinite(a->scale))
        fail(path + "/scale", "must be finite (" + number_text(a->scale) + ")");
      if (!(a->scale > 0.0f))
        fail(path + "/scale", "must be > 0 to be invertible (" + number_text(a->scale) + ")");
      if (a->scale < kMinScale || a->scale > kMaxScale) {
        fail(path + "/scale", "must be in [" + number_text(kMinScale) + ", " +
                                  number_text(kMaxScale) + "] to stay invertible in floats (" +
                                  number_text(a->scale) + ")");
      }
      check_node(node.children[0], path + "/child", depth + 1, edges);
    } else if (std::holds_alternative<Union>(node.data)) {
      for (std::size_t k = 0; k < node.children.size(); ++k) {
        check_node(node.children[k], path + "/children/" + std::to_string(k), depth + 1, edges);
      }
    } else if (const auto* in = std::get_if<Instance>(&node.data)) {
      if (in->master >= scene_.masters.size()) {
        fail(path + "/master",
             "instance of an undefined master (" + std::to_string(in->master) + ")");
      }
      edges.push_back({in->master, path + "/master"});
    } else if (const auto* s = std::get_if<SphereShape>(&node.data)) {
      check_material(path, s->material);
      check_point(path + "/centre", s->centre);
      check_positive(path + "/radius", s->radius, kMaxCoordinate);
    } else if (const auto* b = std::get_if<BoxShape>(&node.data)) {
      check_material(path, b->material);
      check_point(path + "/lo", b->lo);
      check_point(path + "/hi", b->hi);
      if (!(b->hi.x > b->lo.x && b->hi.y > b->lo.y && b->hi.z > b->lo.z)) {
        fail(path + "/hi", "must exceed lo in every axis " + vec_text(b->hi));
      }
    } else if (const auto* c = std::get_if<CylinderShape>(&node.data)) {
      check_material(path, c->material);
      check_point(path + "/a", c->a);
      check_point(path + "/b", c->b);
      if (!(glm::length(c->b - c->a) > 0.0f))
        fail(path + "/b", "must differ from a " + vec_text(c->b));
      check_positive(path + "/radius", c->radius, kMaxCoordinate);
      if (c->segments < 3 || c->segments > kMaxCylinderSegments) {
        fail(path + "/segments", "must be in [3, " + std::to_string(kMaxCylinderSegments) + "] (" +
                                     std::to_string(c->segments) + ")");
      }
    } else if (const auto* q = std::get_if<QuadShape>(&node.data)) {
      check_material(path, q->material);
      check_point(path + "/corner", q->corner);
      check_point(path + "/edge_u", q->edge_u);
      check_point(path + "/edge_v", q->edge_v);
      if (!(glm::length(glm::cross(q->edge_u, q->edge_v)) > 0.0f)) {
        fail(path + "/edge_v", "must not be zero or parallel to edge_u " + vec_text(q->edge_v));
      }
    } else if (const auto* p = std::get_if<PointLightSource>(&node.data)) {
      check_colour(path + "/intensity", p->intensity, kMaxIntensity);
      check_range(path + "/range", p->range);
    } else if (const auto* mesh = std::get_if<MeshShape>(&node.data)) {
      if (mesh->mesh >= scene_.meshes.size())
        fail(path + "/mesh", "no such mesh (" + std::to_string(mesh->mesh) + ")");
      for (int column = 0; column < 3; ++column)
        check_point(path + "/linear", mesh->linear[column]);
      const float det = glm::determinant(mesh->linear);
      if (!std::isfinite(det) || !(std::abs(det) > 1e-18f)) {
        fail(path + "/linear", "must be invertible (determinant " + number_text(det) + ")");
      }
    } else if (const auto* sp = std::get_if<SpotLightSource>(&node.data)) {
      check_colour(path + "/intensity", sp->intensity, kMaxIntensity);
      if (!std::isfinite(sp->cone_degrees) || !(sp->cone_degrees > 0.0f) ||
          sp->cone_degrees > 180.0f) {
        fail(path + "/cone_degrees", "must be in (0, 180] (" + number_text(sp->cone_degrees) + ")");
      }
      check_non_negative(path + "/dropoff", sp->dropoff, 1e4f);
      check_range(path + "/range", sp->range);
      const bool smooth = !(sp->inner_cone_degrees < 0.0f);
      if (smooth && (!std::isfinite(sp->inner_cone_degrees) ||
                     !(sp->inner_cone_degrees < sp->cone_degrees))) {
        fail(path + "/inner_cone_degrees",
             "must be in [0, cone_degrees) (" + number_text(sp->inner_cone_degrees) + ")");
      }
      if (smooth && sp->dropoff != 0.0f)
        fail(path + "/dropoff", "must be 0 with an inner cone (" + number_text(sp->dropoff) + ")");
    }
  }

  // Infinite (no range) or positive.
  static void check_range(const std::string& path, float range) {
    if (std::isnan(range) || !(range > 0.0f))
      fail(path, "must be > 0 (" + number_text(range) + ")");
  }

  // Depth-first over the instance graph without recursion (a chain of masters may be long);
  // a master met again while still open closes a cycle.
  void order_masters() {
    enum class Mark : std::uint8_t { fresh, open, done };
    const std::size_t n = scene_.masters.size();
    std::vector<Mark> mark(n, Mark::fresh);
    struct Frame {
      std::uint32_t master;
      std::size_t next_edge;
    };
    std::vector<Frame> stack;
    for (std::uint32_t start = 0; start < n; ++start) {
      if (mark[start] != Mark::fresh) continue;
      stack.push_back({start, 0});
      mark[start] = Mark::open;
      while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next_edge == edges_[f.master].size()) {
          mark[f.master] = Mark::done;
          order_.push_back(f.master);
          stack.pop_back();
          continue;
        }
        const Edge& e = edges_[f.master][f.next_edge++];
        if (mark[e.master] == Mark::done) continue;
        if (mark[e.master] == Mark::open) {
          std::string cycle;
          bool in_cycle = false;
          for (const Frame& g : stack) {
            in_cycle = in_cycle || g.master == e.master;
            if (in_cycle) cycle += "'" + scene_.masters[g.master].name + "' -> ";
          }
          fail(e.path, "instance cycle: " + cycle + "'" + scene_.masters[e.master].name + "'");
        }
        mark[e.master] = Mark::open;
        stack.push_back({e.master, 0});
      }
    }
  }

  SubtreeTotals sum_node(const SceneNode& node) const {
    SubtreeTotals t;
    if (const auto* a = std::get_if<Affine>(&node.data)) {
      t = sum_node(node.children[0]);
      const double s = std::log10(static_cast<double>(a->scale));
      t.min_log_scale += s;
      t.max_log_scale += s;
    } else if (std::holds_alternative<Union>(node.data)) {
      for (const SceneNode& child : node.children) {
        const SubtreeTotals c = sum_node(child);
        t.lights = add_saturating(t.lights, c.lights);
        t.triangles = add_saturating(t.triangles, c.triangles);
        t.direct_triangles = add_saturating(t.direct_triangles, c.direct_triangles);
        t.site_placements = add_saturating(t.site_placements, c.site_placements);
        t.instance_depth = std::max(t.instance_depth, c.instance_depth);
        t.min_log_scale = std::min(t.min_log_scale, c.min_log_scale);
        t.max_log_scale = std::max(t.max_log_scale, c.max_log_scale);
      }
    } else if (const auto* in = std::get_if<Instance>(&node.data)) {
      const SubtreeTotals& m = totals_[in->master];
      t.lights = m.lights;
      t.triangles = m.triangles;
      t.site_placements = baked(in->master) ? (m.triangles > 0 ? 1 : 0) : placements_unbaked(m);
      t.instance_depth = m.instance_depth + 1;
      t.min_log_scale = m.min_log_scale;
      t.max_log_scale = m.max_log_scale;
    } else {
      t.lights = is_light(node.data) ? 1 : 0;
      const auto* mesh = std::get_if<MeshShape>(&node.data);
      t.triangles = t.direct_triangles =
          mesh ? mesh_triangles_[mesh->mesh] : static_cast<std::uint64_t>(triangles_of(node.data));
      t.min_log_scale = t.max_log_scale = 0.0;
    }
    return t;
  }

  static void check_totals(const SubtreeTotals& t, const std::string& path) {
    if (t.lights > kMaxSceneLights) {
      fail(path, "expands to more than " + std::to_string(kMaxSceneLights) + " lights (" +
                     std::to_string(t.lights) + ")");
    }
    if (t.instance_depth > kMaxInstanceDepth) {
      fail(path, "instances nested more than " + std::to_string(kMaxInstanceDepth) +
                     " masters deep (" + std::to_string(t.instance_depth) + ")");
    }
    const std::uint64_t placements =
        add_saturating(t.site_placements, t.direct_triangles > 0 ? 1 : 0);
    if (placements > kMaxScenePlacements) {
      fail(path, "expands to more than " + std::to_string(kMaxScenePlacements) +
                     " geometry instances (" + std::to_string(placements) + ")");
    }
    if (t.min_log_scale < -kMaxComposedScaleLog10 || t.max_log_scale > kMaxComposedScaleLog10) {
      fail(path, "nested scales multiply to outside [1e-12, 1e12] (10^" +
                     number_text(t.min_log_scale < -kMaxComposedScaleLog10 ? t.min_log_scale
                                                                           : t.max_log_scale) +
                     ")");
    }
  }

  // The triangles the prototypes will hold: the root's own, each unbaked master's own, and each
  // baked master placed from those, once.
  void check_prototype_triangles(const std::vector<Edge>& root_edges) const {
    std::vector<bool> seen(scene_.masters.size(), false);
    std::uint64_t total = root_.direct_triangles;
    std::vector<std::uint32_t> work;
    for (const Edge& e : root_edges) work.push_back(e.master);
    while (!work.empty()) {
      const std::uint32_t m = work.back();
      work.pop_back();
      if (seen[m]) continue;
      seen[m] = true;
      if (baked(m)) {
        total = add_saturating(total, totals_[m].triangles);
      } else {
        total = add_saturating(total, totals_[m].direct_triangles);
        for (const Edge& e : edges_[m]) work.push_back(e.master);
      }
    }
    if (total > kMaxPrototypeTriangles) {
      fail("/root", "geometry needs more than " + std::to_string(kMaxPrototypeTriangles) +
                        " triangles (" + std::to_string(total) + ")");
    }
  }

  const SceneDescription& scene_;
  std::size_t node_count_ = 0;
  std::vector<std::vector<Edge>> edges_;
  std::vector<std::uint32_t> order_;
  std::vector<SubtreeTotals> totals_;
  std::vector<std::uint64_t> mesh_triangles_;  // per scene mesh
  SubtreeTotals root_;
};

}  // namespace

void validate_description(const SceneDescription& scene) {
  Analysis analysis(scene);
}

SceneAnalysis analyze_description(const SceneDescription& scene) {
  return Analysis(scene).result();
}

}  // namespace scenes
