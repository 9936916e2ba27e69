#include "scenes/scene_description.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace scenes {

SceneNode affine_node(const Affine& affine, SceneNode child) {
  SceneNode n;
  n.data = affine;
  n.children.push_back(std::move(child));
  return n;
}

SceneNode translate_node(const glm::vec3& t, SceneNode child) {
  Affine a;
  a.translate = t;
  return affine_node(a, std::move(child));
}

SceneNode union_node(std::vector<SceneNode> children) {
  SceneNode n;
  n.data = Union{};
  n.children = std::move(children);
  return n;
}

SceneNode instance_node(std::uint32_t master) {
  SceneNode n;
  n.data = Instance{master};
  return n;
}

SceneNode sphere_node(std::uint32_t material, const glm::vec3& centre, float radius) {
  SceneNode n;
  n.data = SphereShape{material, centre, radius};
  return n;
}

SceneNode box_node(std::uint32_t material, const glm::vec3& lo, const glm::vec3& hi) {
  SceneNode n;
  n.data = BoxShape{material, lo, hi};
  return n;
}

SceneNode cylinder_node(std::uint32_t material, const glm::vec3& a, const glm::vec3& b,
                        float radius, int segments) {
  SceneNode n;
  n.data = CylinderShape{material, a, b, radius, segments};
  return n;
}

SceneNode quad_node(std::uint32_t material, const glm::vec3& corner, const glm::vec3& edge_u,
                    const glm::vec3& edge_v) {
  SceneNode n;
  n.data = QuadShape{material, corner, edge_u, edge_v};
  return n;
}

SceneNode mesh_node(std::uint32_t mesh, const glm::mat3& linear) {
  SceneNode n;
  n.data = MeshShape{mesh, linear};
  return n;
}

SceneNode point_light_node(const glm::vec3& intensity) {
  SceneNode n;
  n.data = PointLightSource{intensity};
  return n;
}

SceneNode spot_light_node(const glm::vec3& intensity, float cone_degrees, float dropoff) {
  SceneNode n;
  n.data = SpotLightSource{intensity, cone_degrees, dropoff};
  return n;
}

std::uint32_t add_material(SceneDescription& scene, const std::string& name,
                           const renderer::Material& material) {
  scene.materials.push_back({name, material});
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

std::uint32_t add_master(SceneDescription& scene, const std::string& name, SceneNode node) {
  scene.masters.push_back({name, std::move(node)});
  return static_cast<std::uint32_t>(scene.masters.size() - 1);
}

Affine aimed_affine(const glm::vec3& position, const glm::vec3& direction) {
  Affine a;
  a.translate = position;
  const glm::vec3 down(0.0f, 0.0f, -1.0f), d = glm::normalize(direction);
  const glm::vec3 axis = glm::cross(down, d);
  if (glm::length(axis) > 1e-6f) {
    a.rotate_axis = glm::normalize(axis);
    a.rotate_degrees = static_cast<float>(
        std::acos(std::clamp(static_cast<double>(glm::dot(down, d)), -1.0, 1.0)) * 180.0 / M_PI);
  }
  return a;
}

lev::Similarity affine_similarity(const Affine& affine) {
  lev::Similarity xf = lev::make_scale(affine.scale);
  if (affine.rotate_degrees != 0.0f) {
    // Quarter turns get exact sines and cosines, so walls turned by 90 degrees still meet.
    const double degrees = std::fmod(static_cast<double>(affine.rotate_degrees), 360.0);
    double c = 0.0, s = 0.0;
    if (std::fmod(degrees, 90.0) == 0.0) {
      const int quarter = (static_cast<int>(degrees / 90.0) % 4 + 4) % 4;
      c = quarter == 0 ? 1.0 : quarter == 2 ? -1.0 : 0.0;
      s = quarter == 1 ? 1.0 : quarter == 3 ? -1.0 : 0.0;
    } else {
      c = std::cos(degrees * M_PI / 180.0);
      s = std::sin(degrees * M_PI / 180.0);
    }
    const glm::dvec3 a = glm::normalize(glm::dvec3(affine.rotate_axis));
    const double t = 1.0 - c;
    // Rodrigues' formula, column-major: rotation[col][row].
    lev::Similarity r;
    r.rotation[0] =
        glm::vec3(glm::dvec3(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y));
    r.rotation[1] =
        glm::vec3(glm::dvec3(t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x));
    r.rotation[2] =
        glm::vec3(glm::dvec3(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c));
    xf = lev::compose(r, xf);
  }
  return lev::compose(lev::make_translation(affine.translate), xf);
}

const char* node_type_name(const NodeData& data) {
  static constexpr const char* kNames[] = {"affine",     "union",    "instance", "sphere",
                                           "box",        "cylinder", "quad",     "point_light",
                                           "spot_light", "mesh"};
  static_assert(std::variant_size_v<NodeData> == sizeof(kNames) / sizeof(kNames[0]));
  return kNames[data.index()];
}

}  // namespace scenes
