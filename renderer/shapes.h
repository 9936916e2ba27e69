// Triangle meshes for the primitives the scene models use: boxes, cylinders and quads.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/geometry.h"

namespace renderer {

// Axis-aligned box from lo to hi, flat-shaded.
void add_box(TriangleMesh& mesh, const glm::vec3& lo, const glm::vec3& hi);
// Closed cylinder between the centres of its caps a and b, smooth sides, flat caps.
void add_cylinder(TriangleMesh& mesh, const glm::vec3& a, const glm::vec3& b, float radius,
                  int segments = 24);
// Two-sided quad (corner + two edges), normal along cross(edge_u, edge_v).
void add_quad(TriangleMesh& mesh, const glm::vec3& corner, const glm::vec3& edge_u,
              const glm::vec3& edge_v);

}  // namespace renderer
