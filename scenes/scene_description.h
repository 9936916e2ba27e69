// The scene description: everything a scene file says and every built-in scene model builds,
// before any preprocessing (the thesis' "original CSG tree", 4.2-4.3). A camera, Phong materials,
// and one tree of affine, union, instance, primitive and light nodes, plus named masters that are
// defined once and instanced by reference. instantiate_scene (scene_instantiation.h) splits it
// into the light hierarchy and the Embree geometry; scene_file.h reads and writes it as JSON.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "lev/transform.h"
#include "renderer/camera.h"
#include "renderer/directional_light.h"
#include "renderer/geometry.h"
#include "renderer/material.h"
#include "renderer/texture.h"

namespace scenes {

// A similarity (thesis 4.2.2, affine node): x -> translate + rotation(scale * x). Uniform scale
// only, so spheres stay spheres and a light seen through scale s shines with s^2 its intensity.
struct Affine {
  glm::vec3 translate{0.0f};
  glm::vec3 rotate_axis{0.0f, 0.0f, 1.0f};  // right-handed, any non-zero length
  float rotate_degrees = 0.0f;
  float scale = 1.0f;
};

struct Union {};

struct Instance {
  std::uint32_t master = 0;  // index into SceneDescription::masters
};

struct SphereShape {
  std::uint32_t material = 0;
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
};

struct BoxShape {  // axis-aligned in its frame
  std::uint32_t material = 0;
  glm::vec3 lo{0.0f};
  glm::vec3 hi{1.0f};
};

struct CylinderShape {  // closed, between the centres of its caps
  std::uint32_t material = 0;
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f, 0.0f, 1.0f};
  float radius = 1.0f;
  int segments = 24;
};

struct QuadShape {  // two-sided parallelogram corner + s*edge_u + t*edge_v, s, t in [0, 1]
  std::uint32_t material = 0;
  glm::vec3 corner{0.0f};
  glm::vec3 edge_u{1.0f, 0.0f, 0.0f};
  glm::vec3 edge_v{0.0f, 1.0f, 0.0f};
};

// A triangle mesh read from a file (glTF), drawn in its frame after `linear`: any invertible
// 3x3 map, so the non-uniform scale and mirroring that affine nodes cannot express are baked
// into the vertices (normals by the inverse transpose, winding reversed when it mirrors).
struct MeshShape {
  std::uint32_t mesh = 0;  // index into SceneDescription::meshes
  glm::mat3 linear{1.0f};
};

// Lights sit at the origin of their frame (thesis 4.2.2); transforms place, turn and scale them.
// A range (glTF) darkens a light beyond that distance in its frame; infinite means none.
struct PointLightSource {
  glm::vec3 intensity{1.0f};  // RGB, irradiance at distance 1
  float range = std::numeric_limits<float>::infinity();
};

struct SpotLightSource {  // shines along -z of its frame
  glm::vec3 intensity{1.0f};
  float cone_degrees = 90.0f;  // half-angle of Warn's cone (the outer cone of a smooth spot)
  float dropoff = 0.0f;        // Warn exponent
  float range = std::numeric_limits<float>::infinity();
  // Negative: Warn's profile. Otherwise glTF's smooth profile (lev/spot_profile.h), full
  // intensity within this half-angle, in [0, cone_degrees).
  float inner_cone_degrees = -1.0f;
};

using NodeData = std::variant<Affine, Union, Instance, SphereShape, BoxShape, CylinderShape,
                              QuadShape, PointLightSource, SpotLightSource, MeshShape>;

struct SceneNode {
  NodeData data = Union{};
  std::vector<SceneNode> children;  // affine: exactly one; union: any; others: none
};

struct NamedMaterial {
  std::string name;
  renderer::Material material;
};

struct Master {
  std::string name;
  SceneNode node;
};

// One mesh's triangles, one part per material (each part's `material` indexes the scene's).
struct MeshData {
  std::string name;
  std::vector<renderer::TriangleMesh> parts;
};

struct SceneDescription {
  std::string name;  // scene model name, or the file's
  int level = 0;     // model level, 0 when the scene has none
  renderer::Camera camera;
  glm::vec3 ambient{1.0f};
  glm::vec3 background{0.0f};
  std::vector<NamedMaterial> materials;
  std::vector<Master> masters;   // any order; instances refer by index, cycles are invalid
  std::vector<MeshData> meshes;  // what mesh nodes draw; scene files have none
  std::vector<renderer::Texture>
      textures;  // what materials' colour_texture indexes; scene files have none
  // Suns (glTF directional lights) in world space: outside the light hierarchy, shadow-tested
  // at every shading point by every method. Scene files have none.
  std::vector<renderer::DirectionalLight> directional_lights;
  SceneNode root;
};

SceneNode affine_node(const Affine& affine, SceneNode child);
SceneNode translate_node(const glm::vec3& t, SceneNode child);
SceneNode union_node(std::vector<SceneNode> children);
SceneNode instance_node(std::uint32_t master);
SceneNode sphere_node(std::uint32_t material, const glm::vec3& centre, float radius);
SceneNode box_node(std::uint32_t material, const glm::vec3& lo, const glm::vec3& hi);
SceneNode cylinder_node(std::uint32_t material, const glm::vec3& a, const glm::vec3& b,
                        float radius, int segments = 24);
SceneNode quad_node(std::uint32_t material, const glm::vec3& corner, const glm::vec3& edge_u,
                    const glm::vec3& edge_v);
SceneNode mesh_node(std::uint32_t mesh, const glm::mat3& linear);
SceneNode point_light_node(const glm::vec3& intensity);
SceneNode spot_light_node(const glm::vec3& intensity, float cone_degrees, float dropoff);

// Appends and returns the index.
std::uint32_t add_material(SceneDescription& scene, const std::string& name,
                           const renderer::Material& material);
std::uint32_t add_master(SceneDescription& scene, const std::string& name, SceneNode node);

// The placement of a light (which shines along -z) at `position`, turned to shine along
// `direction` (any non-zero length).
Affine aimed_affine(const glm::vec3& position, const glm::vec3& direction);

// The transform an affine node stands for: translate * rotation * scale.
lev::Similarity affine_similarity(const Affine& affine);

// The key a node kind has in scene files ("affine", "union", ...).
const char* node_type_name(const NodeData& data);

}  // namespace scenes
