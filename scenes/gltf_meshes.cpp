#include "scenes/gltf_meshes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "renderer/direction.h"
#include "scenes/gltf_refusal.h"
#include "scenes/scene_validation.h"

namespace scenes {
namespace {

std::vector<glm::vec3> as_vec3(const std::vector<double>& values) {
  std::vector<glm::vec3> out(values.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = glm::vec3(glm::dvec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]));
  }
  return out;
}

// What a scene checks of every mesh vertex and normal (scene_validation.h: finite, within the
// coordinates levrt holds), refused at the attribute's glTF path; the scene check named levrt's
// own mesh (`/meshes/0/parts/0/positions`), a path not in the file.
void check_vectors(const std::vector<glm::vec3>& values, const std::string& where,
                   const std::string& path) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const glm::vec3& v = values[i];
    const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    if (finite && std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
        std::abs(v.z) <= kMaxCoordinate) {
      continue;
    }
    fail_gltf(path, where,
              "element " + std::to_string(i) + " is [" + gltf_number_text(v.x) + ", " +
                  gltf_number_text(v.y) + ", " + gltf_number_text(v.z) +
                  "] (finite values of magnitude at most " + gltf_number_text(kMaxCoordinate) +
                  " are expected)");
  }
}

// The triangles a primitive's mode makes of its vertex list, as the spec numbers them: strip
// triangle i is (i, i+1, i+2) for even i and (i, i+2, i+1) for odd i; fans share vertex 0.
std::vector<glm::uvec3> triangles_of_mode(const std::vector<std::uint32_t>& v, int mode) {
  std::vector<glm::uvec3> triangles;
  if (mode == TINYGLTF_MODE_TRIANGLES || mode < 0) {
    for (std::size_t i = 0; i + 2 < v.size(); i += 3)
      triangles.push_back({v[i], v[i + 1], v[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
      triangles.push_back(i % 2 == 0 ? glm::uvec3(v[i], v[i + 1], v[i + 2])
                                     : glm::uvec3(v[i], v[i + 2], v[i + 1]));
    }
  } else {
    for (std::size_t i = 1; i + 1 < v.size(); ++i) triangles.push_back({v[0], v[i], v[i + 1]});
  }
  return triangles;
}

// The component types glTF allows for a vertex attribute levrt reads (the spec's table of
// attributes, and KHR_mesh_quantization's wider one when extensionsUsed lists it); anything else
// is refused: an UNSIGNED_INT position decoded as it stands, or bytes read as a float-only
// attribute, would draw a scene the file does not describe.
void check_attribute_format(const tinygltf::Model& model, int index, const std::string& attribute,
                            const std::string& where, const std::string& path) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return;
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  const int type = accessor.componentType;
  const bool normalized = accessor.normalized;
  const bool quantized = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                   "KHR_mesh_quantization") != model.extensionsUsed.end();
  const bool is_float = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool is_byte_or_short =
      type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
      type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const bool is_unsigned_normalized =
      normalized && (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                     type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  const bool is_signed_normalized =
      normalized && (type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT);
  bool allowed = is_float;
  std::string expected = "5126 (float)";
  if (attribute == "POSITION") {
    allowed = is_float || (quantized && is_byte_or_short);
    if (!quantized) expected += "; with KHR_mesh_quantization in extensionsUsed, bytes and shorts";
  } else if (attribute == "NORMAL") {
    allowed = is_float || (quantized && is_signed_normalized);
    if (!quantized) {
      expected +=
          "; with KHR_mesh_quantization in extensionsUsed, normalized signed bytes and "
          "shorts";
    }
  } else if (attribute == "TEXCOORD_0") {
    allowed = is_float || is_unsigned_normalized || (quantized && is_byte_or_short);
    expected += ", normalized 5121 or 5123";
    if (!quantized) expected += "; with KHR_mesh_quantization in extensionsUsed, any byte or short";
  }
  if (!allowed) {
    fail_gltf(path, where,
              "accessors[" + std::to_string(index) + "] of component type " + std::to_string(type) +
                  (normalized ? " (normalized)" : "") + " (" + expected + " is expected)");
  }
}

}  // namespace

GltfMeshes::GltfMeshes(const tinygltf::Model& model, const std::string& path, GltfBudget& budget,
                       GltfMaterials& materials, SceneDescription& scene,
                       std::vector<std::string>& warnings)
    : model_(model),
      path_(path),
      budget_(budget),
      materials_(materials),
      scene_(scene),
      warnings_(warnings),
      accessors_(model, path) {}

void GltfMeshes::check_buffers() const {
  accessors_.check_buffers();
}

void GltfMeshes::charge_scene(const std::vector<int>& roots) {
  std::vector<bool> seen(model_.nodes.size(), false);
  std::vector<int> pending(roots.rbegin(), roots.rend());
  while (!pending.empty()) {
    const int index = pending.back();
    pending.pop_back();
    if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size() ||
        seen[static_cast<std::size_t>(index)])
      continue;  // a bad index or a cycle is refused, by name, when the tree is visited
    seen[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < model_.meshes.size())
      charge_mesh(node.mesh);
    pending.insert(pending.end(), node.children.rbegin(), node.children.rend());
  }
}

std::uint64_t GltfMeshes::accessor_count(int index) const {
  return index >= 0 && static_cast<std::size_t>(index) < model_.accessors.size()
             ? model_.accessors[static_cast<std::size_t>(index)].count
             : 0;
}

// Each triangle primitive as read_primitive builds it: its vertices read, the flat ones made
// when it has no normals, and its triangles; an accessor counted again by every primitive.
void GltfMeshes::charge_mesh(int index) {
  if (charged_meshes_.empty()) charged_meshes_.assign(model_.meshes.size(), false);
  if (charged_meshes_[static_cast<std::size_t>(index)]) return;
  charged_meshes_[static_cast<std::size_t>(index)] = true;
  const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(index)];
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    if (primitive.mode >= 0 && primitive.mode < TINYGLTF_MODE_TRIANGLES) continue;
    const auto position = primitive.attributes.find("POSITION");
    const std::uint64_t vertices =
        position == primitive.attributes.end() ? 0 : accessor_count(position->second);
    const std::uint64_t corners =
        primitive.indices >= 0 ? accessor_count(primitive.indices) : vertices;
    const std::uint64_t triangles = primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
                                            primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN
                                        ? (corners >= 2 ? corners - 2 : 0)
                                        : corners / 3;
    const bool flat = primitive.attributes.count("NORMAL") == 0;
    const std::uint64_t built = vertices + (flat ? 3 * triangles : 0);
    const std::string where = "meshes[" + std::to_string(index) + "].primitives[" +
                              std::to_string(p) + "] (" + std::to_string(built) + " vertices and " +
                              std::to_string(triangles) + " triangles as built)";
    budget_.charge(built, kGltfBytesPerVertex, where);
    budget_.charge(triangles, kGltfBytesPerTriangle, where);
    materials_.charge_material(primitive.material);
  }
}

renderer::TriangleMesh GltfMeshes::read_primitive(const tinygltf::Primitive& primitive,
                                                  const std::string& where) {
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end())
    fail_gltf(path_, where + ".attributes.POSITION", "missing");
  for (const auto& [attribute, index] : primitive.attributes) {
    if (attribute == "POSITION" || attribute == "NORMAL" || attribute == "TEXCOORD_0")
      check_attribute_format(model_, index, attribute, where + ".attributes." + attribute, path_);
  }
  renderer::TriangleMesh part;
  part.positions = as_vec3(
      accessors_.read(position->second, {TINYGLTF_TYPE_VEC3}, where + ".attributes.POSITION"));
  check_vectors(part.positions, where + ".attributes.POSITION", path_);
  const auto vertex_count = part.positions.size();
  std::vector<std::uint32_t> vertices;
  if (primitive.indices >= 0) {
    const std::string indices_where = where + ".indices";
    if (static_cast<std::size_t>(primitive.indices) < model_.accessors.size()) {
      const int type = model_.accessors[static_cast<std::size_t>(primitive.indices)].componentType;
      if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
          type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
          type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail_gltf(path_, indices_where, "component type " + std::to_string(type));
    }
    for (const double index :
         accessors_.read(primitive.indices, {TINYGLTF_TYPE_SCALAR}, indices_where)) {
      if (index >= static_cast<double>(vertex_count))
        fail_gltf(path_, indices_where,
                  "vertex " + gltf_number_text(index) + " of " + std::to_string(vertex_count));
      vertices.push_back(static_cast<std::uint32_t>(index));
    }
  } else {
    for (std::size_t i = 0; i < vertex_count; ++i)
      vertices.push_back(static_cast<std::uint32_t>(i));
  }
  part.triangles = triangles_of_mode(vertices, primitive.mode);
  const auto normal = primitive.attributes.find("NORMAL");
  const auto uv = primitive.attributes.find("TEXCOORD_0");
  if (uv != primitive.attributes.end()) {
    const std::vector<double> values =
        accessors_.read(uv->second, {TINYGLTF_TYPE_VEC2}, where + ".attributes.TEXCOORD_0");
    if (values.size() != 2 * vertex_count)
      fail_gltf(
          path_, where + ".attributes.TEXCOORD_0",
          std::to_string(values.size() / 2) + " for " + std::to_string(vertex_count) + " vertices");
    for (std::size_t i = 0; i < vertex_count; ++i)
      part.uvs.emplace_back(static_cast<float>(values[2 * i]),
                            static_cast<float>(values[2 * i + 1]));
  }
  if (normal != primitive.attributes.end()) {
    part.normals = as_vec3(
        accessors_.read(normal->second, {TINYGLTF_TYPE_VEC3}, where + ".attributes.NORMAL"));
    check_vectors(part.normals, where + ".attributes.NORMAL", path_);
    if (part.normals.size() != vertex_count)
      fail_gltf(path_, where + ".attributes.NORMAL",
                std::to_string(part.normals.size()) + " for " + std::to_string(vertex_count) +
                    " vertices");
    return part;
  }
  // No normals: flat ones (the spec), so every triangle gets its own three vertices.
  renderer::TriangleMesh flat;
  for (const glm::uvec3& t : part.triangles) {
    const glm::vec3 n = renderer::robust_normalize(glm::cross(
        part.positions[t.y] - part.positions[t.x], part.positions[t.z] - part.positions[t.x]));
    const auto base = static_cast<std::uint32_t>(flat.positions.size());
    for (int c = 0; c < 3; ++c) {
      flat.positions.push_back(part.positions[t[c]]);
      flat.normals.push_back(n);
      if (!part.uvs.empty()) flat.uvs.push_back(part.uvs[t[c]]);
    }
    flat.triangles.emplace_back(base, base + 1, base + 2);
  }
  return flat;
}

// The scene mesh of glTF mesh `index` (converted once), or kNoIndex when it has no triangles.
std::uint32_t GltfMeshes::scene_mesh(int index, const std::string& where) {
  if (index >= static_cast<int>(model_.meshes.size()))
    fail_gltf(path_, where + ".mesh", std::to_string(index));
  if (mesh_of_.empty()) mesh_of_.assign(model_.meshes.size(), kUnconverted);
  std::uint32_t& slot = mesh_of_[static_cast<std::size_t>(index)];
  if (slot != kUnconverted) return slot;
  charge_mesh(index);
  const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(index)];
  MeshData data;
  data.name = mesh.name;
  std::vector<int> skipped_modes;
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string primitive_where =
        "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(p) + "]";
    if (primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
      fail_gltf(path_, primitive_where + ".mode", std::to_string(primitive.mode));
    if (primitive.mode >= 0 && primitive.mode < TINYGLTF_MODE_TRIANGLES) {
      skipped_modes.push_back(primitive.mode);
      continue;
    }
    // The spec: a primitive without POSITION is not rendered.
    if (primitive.attributes.count("POSITION") == 0) {
      if (positionless_primitives_++ == 0) first_positionless_ = primitive_where;
      continue;
    }
    renderer::TriangleMesh part = read_primitive(primitive, primitive_where);
    part.material = materials_.scene_material(primitive.material, primitive_where);
    if (!part.triangles.empty()) data.parts.push_back(std::move(part));
  }
  if (!skipped_modes.empty()) {
    warnings_.push_back("mesh " + std::to_string(index) + " '" + mesh.name +
                        "': " + std::to_string(skipped_modes.size()) +
                        " primitive(s) of points or lines skipped (mode " +
                        std::to_string(skipped_modes.front()) + ")");
  }
  if (data.parts.empty()) {
    slot = kNoMesh;
    return slot;
  }
  glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const renderer::TriangleMesh& part : data.parts) {
    for (const glm::vec3& p : part.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  mesh_bounds_.push_back({lo, hi});
  scene_.meshes.push_back(std::move(data));
  slot = static_cast<std::uint32_t>(scene_.meshes.size() - 1);
  return slot;
}

}  // namespace scenes
