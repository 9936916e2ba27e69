// The renderable geometry of a scene: prototypes (triangle meshes and spheres, each with a
// material) placed by similarity transforms. Embree allows one instance level, so nested scene
// instancing is flattened to one level here: a prototype is stored once, placed many times.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lev/transform.h"

namespace renderer {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // per vertex, for smooth shading; same size as positions
  std::vector<glm::uvec3> triangles;
  std::uint32_t material = 0;
  std::vector<glm::vec2> uvs;  // texture coordinates per vertex, or empty (no texture lookups)
};

struct Sphere {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
  std::uint32_t material = 0;
};

struct Prototype {
  std::vector<TriangleMesh> meshes;
  std::vector<Sphere> spheres;
};

struct PlacedPrototype {
  std::uint32_t prototype = 0;
  lev::Similarity world_from_object;
};

struct Geometry {
  std::vector<Prototype> prototypes;
  std::vector<PlacedPrototype> instances;
};

}  // namespace renderer
