#include "renderer/shapes.h"

#include <cmath>

#include "renderer/direction.h"

namespace renderer {
namespace {

void add_face(TriangleMesh& mesh, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
              const glm::vec3& p3, const glm::vec3& normal) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (const glm::vec3& p : {p0, p1, p2, p3}) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(normal);
  }
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return robust_normalize(glm::cross(n, helper));
}

}  // namespace

void add_quad(TriangleMesh& mesh, const glm::vec3& corner, const glm::vec3& edge_u,
              const glm::vec3& edge_v) {
  const glm::vec3 n = robust_normalize(glm::cross(edge_u, edge_v));
  add_face(mesh, corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v, n);
}

void add_box(TriangleMesh& mesh, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  add_quad(mesh, lo, y, x);      // bottom (-z)
  add_quad(mesh, lo + z, x, y);  // top (+z)
  add_quad(mesh, lo, x, z);      // front (-y)
  add_quad(mesh, lo + y, z, x);  // back (+y)
  add_quad(mesh, lo, z, y);      // left (-x)
  add_quad(mesh, lo + x, y, z);  // right (+x)
}

void add_cylinder(TriangleMesh& mesh, const glm::vec3& a, const glm::vec3& b, float radius,
                  int segments) {
  const glm::vec3 axis = robust_normalize(b - a);
  const glm::vec3 u = perpendicular(axis), v = glm::cross(axis, u);
  const float step = 2.0f * static_cast<float>(M_PI) / static_cast<float>(segments);
  for (int i = 0; i < segments; ++i) {
    const float t0 = step * static_cast<float>(i), t1 = step * static_cast<float>(i + 1);
    const glm::vec3 r0 = std::cos(t0) * u + std::sin(t0) * v;
    const glm::vec3 r1 = std::cos(t1) * u + std::sin(t1) * v;
    // Side: smooth normals.
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& [p, n] : {std::pair{a + radius * r0, r0}, std::pair{a + radius * r1, r1},
                               std::pair{b + radius * r1, r1}, std::pair{b + radius * r0, r0}}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
    // Caps: flat.
    const auto cap = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& [p, n] :
         {std::pair{b, axis}, std::pair{b + radius * r0, axis}, std::pair{b + radius * r1, axis},
          std::pair{a, -axis}, std::pair{a + radius * r1, -axis},
          std::pair{a + radius * r0, -axis}}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
    }
    mesh.triangles.push_back({cap, cap + 1, cap + 2});
    mesh.triangles.push_back({cap + 3, cap + 4, cap + 5});
  }
}

}  // namespace renderer
