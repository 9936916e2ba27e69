#include "scenes/robot.h"

#include "renderer/shapes.h"

namespace scenes {
namespace {

renderer::TriangleMesh transformed(renderer::TriangleMesh mesh, const lev::Similarity& xf) {
  for (glm::vec3& p : mesh.positions) p = lev::apply_point(xf, p);
  for (glm::vec3& n : mesh.normals) n = lev::apply_direction(xf, n);
  return mesh;
}

}  // namespace

void add_robot(renderer::Prototype& prototype, const lev::Similarity& xf, const RobotMaterials& m) {
  renderer::TriangleMesh tyre, metal, body;
  tyre.material = m.tyre;
  metal.material = m.metal;
  body.material = m.body;
  // Wheel: axis along x, resting on the floor.
  renderer::add_cylinder(tyre, {-0.08f, 0.0f, 0.5f}, {0.08f, 0.0f, 0.5f}, 0.5f, 32);
  renderer::add_cylinder(metal, {-0.1f, 0.0f, 0.5f}, {0.1f, 0.0f, 0.5f}, 0.1f, 12);
  // Fork and seat post.
  renderer::add_cylinder(metal, {0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.3f}, 0.05f, 12);
  renderer::add_box(metal, {-0.25f, -0.12f, 1.3f}, {0.25f, 0.12f, 1.36f});
  // Body and arms (held out for balance).
  renderer::add_box(body, {-0.3f, -0.2f, 1.36f}, {0.3f, 0.2f, 2.1f});
  renderer::add_cylinder(metal, {-0.3f, 0.0f, 1.95f}, {-0.85f, 0.15f, 1.75f}, 0.06f, 12);
  renderer::add_cylinder(metal, {0.3f, 0.0f, 1.95f}, {0.85f, 0.15f, 1.75f}, 0.06f, 12);
  renderer::add_cylinder(metal, {0.0f, 0.0f, 2.1f}, {0.0f, 0.0f, 2.2f}, 0.08f, 12);
  prototype.meshes.push_back(transformed(tyre, xf));
  prototype.meshes.push_back(transformed(metal, xf));
  prototype.meshes.push_back(transformed(body, xf));
  renderer::Sphere head;
  head.centre = lev::apply_point(xf, {0.0f, 0.0f, 2.45f});
  head.radius = 0.27f * xf.scale;
  head.material = m.head;
  prototype.spheres.push_back(head);
}

}  // namespace scenes
