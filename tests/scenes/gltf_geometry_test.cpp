// glTF triangle meshes (scenes/gltf_scene.h): every index type, strides, sparse accessors and
// normalized integers read as the spec says; flat normals when none are given; non-uniform scale
// and mirroring baked with normals and winding right; a mesh drawn by several nodes is one Embree
// prototype placed several times; points and lines skipped with one warning; bad accessors fail
// with one line.

#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "scenes/gltf_scene.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/gltf_builder.h"
#include "tests/support/gltf_refusal.h"

namespace {

using levrt_test::GltfBuilder;

constexpr char kGeometryPath[] = "mesh.gltf";

scenes::SceneDescription parse_geometry(GltfBuilder& builder) {
  return scenes::parse_gltf_scene(builder.text(), kGeometryPath);
}

const renderer::TriangleMesh& only_part(const scenes::SceneDescription& scene) {
  EXPECT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes.at(0).parts.size(), 1u);
  return scene.meshes.at(0).parts.at(0);
}

const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<glm::uvec3> kQuadTriangles = {{0, 1, 2}, {0, 2, 3}};

tinygltf::Node mesh_node(int mesh) {
  tinygltf::Node node;
  node.mesh = mesh;
  return node;
}

// Every triangle of the scene's geometry in world space, with its vertex normals.
struct WorldTriangle {
  glm::vec3 p[3];
  glm::vec3 n[3];
};

std::vector<WorldTriangle> world_triangles(const renderer::Scene& scene) {
  std::vector<WorldTriangle> out;
  for (const renderer::PlacedPrototype& placed : scene.geometry.instances) {
    for (const renderer::TriangleMesh& mesh : scene.geometry.prototypes[placed.prototype].meshes) {
      for (const glm::uvec3& t : mesh.triangles) {
        WorldTriangle w;
        for (int c = 0; c < 3; ++c) {
          w.p[c] = lev::apply_point(placed.world_from_object, mesh.positions[t[c]]);
          w.n[c] = lev::apply_direction(placed.world_from_object, mesh.normals[t[c]]);
        }
        out.push_back(w);
      }
    }
  }
  return out;
}

void expect_vec3_near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// Makes the builder's first accessor sparse: `count` replaced elements, the first at `index`,
// its value (1, 2, 3).
void make_sparse(GltfBuilder& builder, int count, std::uint32_t index) {
  tinygltf::Accessor& accessor = builder.model.accessors[0];
  accessor.sparse.isSparse = true;
  accessor.sparse.count = count;
  accessor.sparse.indices.bufferView = builder.add_view(std::vector<std::uint32_t>{index});
  accessor.sparse.indices.byteOffset = 0;
  accessor.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  accessor.sparse.values.bufferView = builder.add_view(std::vector<float>{1, 2, 3});
  accessor.sparse.values.byteOffset = 0;
}

template <typename Index>
void check_index_type(int component_type) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  const int indices = builder.add_accessor(builder.add_view(std::vector<Index>{0, 1, 2, 0, 2, 3}),
                                           component_type, TINYGLTF_TYPE_SCALAR, 6);
  builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}}, indices)));
  const scenes::SceneDescription scene = parse_geometry(builder);
  // No normals: flat, so each triangle has three vertices of its own, in the file's order.
  const renderer::TriangleMesh& part = only_part(scene);
  ASSERT_EQ(part.triangles.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(part.positions[part.triangles[t][c]], kQuad[kQuadTriangles[t][c]]);
      EXPECT_EQ(part.normals[part.triangles[t][c]], glm::vec3(0, 0, 1));
    }
  }
}

TEST(GltfGeometry, EveryIndexTypeReadsTheSameTriangles) {
  check_index_type<std::uint8_t>(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  check_index_type<std::uint16_t>(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  check_index_type<std::uint32_t>(TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
}

TEST(GltfGeometry, UnindexedStripsAndFans) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  const int strip_positions = builder.add_vec3s({kQuad[0], kQuad[1], kQuad[3], kQuad[2]});
  builder.add_node(
      mesh_node(builder.add_mesh({{"POSITION", positions}}, -1, TINYGLTF_MODE_TRIANGLE_FAN)));
  builder.add_node(mesh_node(
      builder.add_mesh({{"POSITION", strip_positions}}, -1, TINYGLTF_MODE_TRIANGLE_STRIP)));
  builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
  const scenes::SceneDescription scene = parse_geometry(builder);
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(scene.meshes[0].parts.at(0).triangles.size(), 2u);  // fan 0-1-2, 0-2-3
  EXPECT_EQ(scene.meshes[1].parts.at(0).triangles.size(), 2u);  // strip 0-1-2, 1-3-2
  EXPECT_EQ(scene.meshes[2].parts.at(0).triangles.size(), 1u);  // list: one whole triangle
  // Every triangle winds counter-clockwise about +z, the strip's second one too.
  for (std::size_t m = 0; m < 3; ++m) {
    const renderer::TriangleMesh& part = scene.meshes[m].parts[0];
    for (const glm::uvec3& t : part.triangles)
      EXPECT_EQ(part.normals[t.x], glm::vec3(0, 0, 1)) << "mesh " << m;
  }
}

TEST(GltfGeometry, InterleavedStridesAndGivenNormals) {
  GltfBuilder builder;
  // position xyz, normal xyz, per vertex: one view with a 24-byte stride, two accessors into it.
  std::vector<float> interleaved;
  const glm::vec3 normal = glm::normalize(glm::vec3(0, 1, 1));
  for (const glm::vec3& p : kQuad)
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, normal.x, normal.y, normal.z});
  const int view = builder.add_view(interleaved, 24);
  const int positions =
      builder.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
  const int normals =
      builder.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4, false, 12);
  const int indices =
      builder.add_accessor(builder.add_view(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
  builder.add_node(
      mesh_node(builder.add_mesh({{"POSITION", positions}, {"NORMAL", normals}}, indices)));
  const renderer::TriangleMesh part = only_part(parse_geometry(builder));
  EXPECT_EQ(part.positions, kQuad);
  EXPECT_EQ(part.triangles, kQuadTriangles);
  for (const glm::vec3& n : part.normals) EXPECT_EQ(n, normal);
}

TEST(GltfGeometry, SparseAccessorsSubstituteTheirElements) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  // Vertex 2 moves to (5, 6, 7); a second accessor has no view: zeros but for its substitution.
  const int indices_view = builder.add_view(std::vector<std::uint16_t>{2});
  const int values_view = builder.add_view(std::vector<float>{5, 6, 7});
  tinygltf::Accessor& accessor = builder.model.accessors[static_cast<std::size_t>(positions)];
  accessor.sparse.isSparse = true;
  accessor.sparse.count = 1;
  accessor.sparse.indices.bufferView = indices_view;
  accessor.sparse.indices.byteOffset = 0;
  accessor.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  accessor.sparse.values.bufferView = values_view;
  accessor.sparse.values.byteOffset = 0;
  tinygltf::Accessor zeros = accessor;
  zeros.bufferView = -1;
  builder.model.accessors.push_back(zeros);
  const int zero_positions = static_cast<int>(builder.model.accessors.size() - 1);
  const int normals = builder.add_vec3s(std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)));
  builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}, {"NORMAL", normals}})));
  builder.add_node(
      mesh_node(builder.add_mesh({{"POSITION", zero_positions}, {"NORMAL", normals}})));
  const scenes::SceneDescription scene = parse_geometry(builder);
  ASSERT_EQ(scene.meshes.size(), 2u);
  const std::vector<glm::vec3> moved = {kQuad[0], kQuad[1], {5, 6, 7}, kQuad[3]};
  EXPECT_EQ(scene.meshes[0].parts.at(0).positions, moved);
  const std::vector<glm::vec3> only_substituted = {{0, 0, 0}, {0, 0, 0}, {5, 6, 7}, {0, 0, 0}};
  EXPECT_EQ(scene.meshes[1].parts.at(0).positions, only_substituted);
}

TEST(GltfGeometry, NormalizedIntegersDecodeAsTheSpecSays) {
  GltfBuilder builder;
  builder.model.extensionsUsed.push_back("KHR_mesh_quantization");  // for the short positions
  // Signed shorts: -32768 clamps to -1, 32767 is 1; unsigned bytes: 255 is 1, 51 is 0.2.
  const int positions = builder.add_accessor(
      builder.add_view(std::vector<std::int16_t>{-32768, 0, 0, 32767, 0, 0, 0, 32767, 0, 0}),
      TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3, 3, true);
  const int uvs =
      builder.add_accessor(builder.add_view(std::vector<std::uint8_t>{0, 255, 51, 0, 255, 255}),
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC2, 3, true);
  const int normals = builder.add_vec3s(std::vector<glm::vec3>(3, glm::vec3(0, 0, 1)));
  builder.add_node(mesh_node(
      builder.add_mesh({{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}})));
  const renderer::TriangleMesh part = only_part(parse_geometry(builder));
  const std::vector<glm::vec3> expected = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(part.positions, expected);
  ASSERT_EQ(part.uvs.size(), 3u);
  EXPECT_EQ(part.uvs[0], glm::vec2(0.0f, 1.0f));
  EXPECT_FLOAT_EQ(part.uvs[1].x, 0.2f);
  EXPECT_EQ(part.uvs[2], glm::vec2(1.0f, 1.0f));
}

// One triangle in the plane x + y = 1 (normal (1, 1, 0)/sqrt 2) drawn by a node of `scale`.
std::vector<WorldTriangle> scaled_triangle(const std::vector<double>& scale) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s({{1, 0, 0}, {0, 1, 0}, {0, 1, 1}});
  const int normals =
      builder.add_vec3s(std::vector<glm::vec3>(3, glm::normalize(glm::vec3(1, 1, 0))));
  tinygltf::Node node = mesh_node(builder.add_mesh({{"POSITION", positions}, {"NORMAL", normals}}));
  node.scale = scale;
  builder.add_node(node);
  return world_triangles(scenes::instantiate_scene(parse_geometry(builder)));
}

TEST(GltfGeometry, NonUniformScaleTransformsNormalsByTheInverseTranspose) {
  const std::vector<WorldTriangle> triangles = scaled_triangle({2, 1, 1});
  ASSERT_EQ(triangles.size(), 1u);
  expect_vec3_near(triangles[0].p[0], {2, 0, 0});
  expect_vec3_near(triangles[0].p[1], {0, 1, 0});
  // The plane x/2 + y = 1: normal along (1/2, 1, 0), perpendicular to both edges.
  const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 1.0f, 0.0f));
  for (const glm::vec3& n : triangles[0].n) expect_vec3_near(n, expected);
  EXPECT_NEAR(glm::dot(expected, triangles[0].p[1] - triangles[0].p[0]), 0.0f, 1e-5f);
}

TEST(GltfGeometry, MirroringKeepsWindingAndNormalsOnTheSameSide) {
  for (const std::vector<double>& scale :
       {std::vector<double>{1, 1, 1}, std::vector<double>{-1, 1, 1},
        std::vector<double>{-1, -2, 3}}) {
    const std::vector<WorldTriangle> triangles = scaled_triangle(scale);
    ASSERT_EQ(triangles.size(), 1u);
    const WorldTriangle& t = triangles[0];
    const glm::vec3 winding = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    // The file's triangle winds counter-clockwise about its normal; so must the placed one.
    EXPECT_GT(glm::dot(winding, t.n[0]), 0.0f) << scale[0] << " " << scale[1] << " " << scale[2];
    expect_vec3_near(t.p[0], {static_cast<float>(scale[0]), 0, 0});
  }
}

TEST(GltfGeometry, AMeshDrawnByManyNodesIsOnePrototypePlacedManyTimes) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  const int mesh = builder.add_mesh({{"POSITION", positions}});
  tinygltf::Node moved = mesh_node(mesh);
  moved.translation = {5, 0, 0};
  tinygltf::Node turned = mesh_node(mesh);
  turned.rotation = {0, 0.70710678, 0, 0.70710678};
  turned.scale = {3, 3, 3};
  builder.add_node(mesh_node(mesh));
  builder.add_node(moved);
  // A child of the turned node draws it too, through the composed transform.
  const int child = builder.add_node(moved, false);
  turned.children = {child};
  builder.add_node(turned);
  const renderer::Scene scene = scenes::instantiate_scene(parse_geometry(builder));
  EXPECT_EQ(scene.geometry.prototypes.size(), 1u);
  EXPECT_EQ(scene.geometry.instances.size(), 4u);  // the turned node draws the mesh itself too
  // The child: turned by 90 degrees about +y and scaled by 3 after moving 5 along x: at z = -15.
  const std::vector<WorldTriangle> triangles = world_triangles(scene);
  ASSERT_EQ(triangles.size(), 4u);  // four vertices listed: one triangle per placement
  bool found = false;
  for (const WorldTriangle& t : triangles)
    found = found || glm::length(t.p[0] - glm::vec3(0, 0, -15)) < 1e-4f;
  EXPECT_TRUE(found);

  // A node that stretches the mesh needs a prototype of its own; a second alike shares it.
  tinygltf::Node stretched = mesh_node(mesh);
  stretched.scale = {1, 2, 1};
  builder.add_node(stretched);
  stretched.translation = {0, 9, 0};
  builder.add_node(stretched);
  const renderer::Scene with_stretched = scenes::instantiate_scene(parse_geometry(builder));
  EXPECT_EQ(with_stretched.geometry.prototypes.size(), 2u);
  EXPECT_EQ(with_stretched.geometry.instances.size(), 6u);
}

TEST(GltfGeometry, PointsAndLinesAreSkippedWithOneWarningNamingTheMesh) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  builder.add_node(
      mesh_node(builder.add_mesh({{"POSITION", positions}}, -1, TINYGLTF_MODE_POINTS, -1, "dots")));
  builder.add_node(
      mesh_node(builder.add_mesh({{"POSITION", positions}}, -1, TINYGLTF_MODE_LINE, -1, "wires")));
  builder.add_node(mesh_node(
      builder.add_mesh({{"POSITION", positions}}, -1, TINYGLTF_MODE_TRIANGLES, -1, "triangle")));
  testing::internal::CaptureStderr();
  const scenes::SceneDescription scene = parse_geometry(builder);
  const std::string warnings = testing::internal::GetCapturedStderr();
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "triangle");
  EXPECT_NE(warnings.find("mesh 0 'dots'"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("mesh 1 'wires'"), std::string::npos) << warnings;
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 2) << warnings;

  // With nothing else, one more line says that only the background remains.
  builder.model.scenes[0].nodes.pop_back();
  testing::internal::CaptureStderr();
  EXPECT_TRUE(parse_geometry(builder).meshes.empty());
  const std::string alone = testing::internal::GetCapturedStderr();
  EXPECT_NE(alone.find("nothing to render"), std::string::npos) << alone;
  EXPECT_EQ(std::count(alone.begin(), alone.end(), '\n'), 3) << alone;
}

void expect_refused(GltfBuilder& builder, const std::string& problem) {
  levrt_test::expect_gltf_refused(builder.text(), kGeometryPath, problem);
}

TEST(GltfGeometry, BadAccessorsFailWithOneLine) {
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s(kQuad);
    const int indices =
        builder.add_accessor(builder.add_view(std::vector<std::uint8_t>{0, 1, 4}),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_SCALAR, 3);
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}}, indices)));
    expect_refused(builder, "meshes[0].primitives[0].indices: vertex 4 of 4");
  }
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s(kQuad);
    builder.model.accessors[0].count = 5;
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
    expect_refused(builder, "accessors[0]: 5 elements beyond the view's 48 bytes");
  }
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s(kQuad);
    builder.model.bufferViews[0].byteStride = 8;
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
    expect_refused(builder, "accessors[0]: byteStride 8 below the element's 12 bytes");
  }
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s(kQuad);
    make_sparse(builder, 1, 7);
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
    expect_refused(builder, "accessors[0].sparse.indices: 7 beyond the count 4");
  }
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s(kQuad);
    const int indices = builder.add_vec3s(kQuad);
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}}, indices)));
    expect_refused(builder, "meshes[0].primitives[0].indices: component type 5126");
  }
  {
    GltfBuilder builder;
    const int positions = builder.add_vec3s({{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}});
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
    expect_refused(builder, "attributes.POSITION: element 2 is [0, nan, 0]");
  }
}

TEST(GltfGeometry, ASparseCountAboveTheAccessorsIsRefusedSayingWhy) {
  GltfBuilder builder;
  const int positions = builder.add_vec3s(kQuad);
  make_sparse(builder, 2147483647, 0);
  builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
  expect_refused(builder,
                 "accessors[0].sparse.count: 2147483647 (from 1 to the accessor's count, 4, is "
                 "expected)");
}

TEST(GltfGeometry, AnAttributeOfAComponentTypeGltfDoesNotAllowIsRefused) {
  // Unsigned int positions (allowed by no extension), byte positions without
  // KHR_mesh_quantization in extensionsUsed, byte normals that are not normalized.
  {
    GltfBuilder builder;
    const int positions = builder.add_accessor(
        builder.add_view(std::vector<std::uint32_t>{0, 0, 0, 1, 0, 0, 0, 1, 0}),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_VEC3, 3);
    builder.add_node(mesh_node(builder.add_mesh({{"POSITION", positions}})));
    expect_refused(builder,
                   "meshes[0].primitives[0].attributes.POSITION: accessors[0] of component type "
                   "5125 (5126 (float); with KHR_mesh_quantization in extensionsUsed, bytes and "
                   "shorts is expected)");
  }
  for (const bool quantized : {false, true}) {
    GltfBuilder builder;
    if (quantized) builder.model.extensionsUsed.push_back("KHR_mesh_quantization");
    const int positions =
        builder.add_accessor(builder.add_view(std::vector<std::int8_t>{0, 0, 0, 1, 0, 0, 0, 1, 0}),
                             TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, 3);
    std::map<std::string, int> attributes = {{"POSITION", positions}};
    if (quantized) {
      attributes["NORMAL"] = builder.add_accessor(
          builder.add_view(std::vector<std::int8_t>{0, 0, 1, 0, 0, 1, 0, 0, 1}),
          TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, 3);
    }
    builder.add_node(mesh_node(builder.add_mesh(attributes)));
    expect_refused(builder, quantized ? "attributes.NORMAL: accessors[1] of component type 5120 ("
                                      : "attributes.POSITION: accessors[0] of component type "
                                        "5120 (");
  }
}

}  // namespace

namespace {

// A vertex or normal that is not finite, or beyond the 1e6 levrt's coordinates reach, is refused
// at its attribute's glTF path; the scene check named levrt's own mesh
// (`scene: /meshes/0/parts/0/positions: must be finite [nan, 0, 0]`), a path not in the file.
TEST(GltfGeometry, AVertexOrNormalLevrtCannotHoldIsRefusedAtItsAttribute) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case {
    std::vector<glm::vec3> positions, normals;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {{{0, 0, 0}, {nan, 0, 0}, {0, 1, 0}},
       {},
       ": meshes[0].primitives[0].attributes.POSITION: "
       "element 1 is [nan, 0, 0] (finite values"},
      {{{0, 0, 0}, {2e6f, 0, 0}, {0, 1, 0}},
       {},
       ": meshes[0].primitives[0].attributes.POSITION: element 1 is [2000000, 0, 0] (finite "
       "values of magnitude at most 1000000 are expected)"},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
       {{0, 0, 1}, {0, 0, 1}, {0, 0, inf}},
       ": meshes[0].primitives[0].attributes.NORMAL: element 2 is [0, 0, inf]"},
  };
  for (const Case& c : cases) {
    GltfBuilder builder;
    std::map<std::string, int> attributes = {{"POSITION", builder.add_vec3s(c.positions)}};
    if (!c.normals.empty()) attributes["NORMAL"] = builder.add_vec3s(c.normals);
    builder.add_node(mesh_node(builder.add_mesh(attributes)));
    levrt_test::expect_gltf_refused(builder.text(), kGeometryPath, c.problem);
  }
}

}  // namespace
