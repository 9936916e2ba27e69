#include "scenes/gltf_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "renderer/direction.h"
#include "scenes/gltf_budget.h"
#include "scenes/gltf_document.h"
#include "scenes/gltf_materials.h"
#include "scenes/gltf_node_tree.h"
#include "scenes/gltf_refusal.h"
#include "scenes/gltf_schema.h"
#include "scenes/scene_file.h"
#include "scenes/scene_folder.h"
#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number_text(double value) {
  return gltf_number_text(value);
}

[[noreturn]] void fail(const std::string& path, const std::string& what, const std::string& value) {
  fail_gltf(path, what, value);
}

std::string first_line(const std::string& text) {
  const std::size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

// Images keep their encoded bytes here; the importer decodes only those a material samples.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = 0;
  return true;
}

// tinygltf's file access, confined to what check_gltf_document approved in the scene's folder.
struct FolderReader {
  std::string gltf_path;
  std::string folder;
  GltfExternalFiles files;
  std::string error;  // the first refusal, one line, thrown once tinygltf returns
};

// Every name "exists": read_checked_file decides, with a reason (and tinygltf then never tries
// the working folder as its second place to look).
bool accept_any_name(const std::string&, void*) {
  return true;
}
// No ~ or $VAR expansion (tinygltf's default runs wordexp on the name).
std::string keep_name(const std::string& name, void*) {
  return name;
}

bool read_checked_file(std::vector<unsigned char>* out, std::string* error, const std::string& name,
                       void* context) {
  auto& reader = *static_cast<FolderReader*>(context);
  const auto found = reader.files.find(name);
  try {
    if (found == reader.files.end())
      throw std::invalid_argument("'" + name + "': not a file the glTF's URIs name");
    read_regular_file(found->second.canonical_path, found->second.bytes, "file the glTF names",
                      *out);
    return true;
  } catch (const std::invalid_argument& e) {
    if (reader.error.empty()) reader.error = reader.gltf_path + ": " + e.what();
    if (error) *error = e.what();
    return false;
  }
}

bool write_nothing(std::string* error, const std::string&, const std::vector<unsigned char>&,
                   void*) {
  if (error) *error = "levrt never writes glTF files";
  return false;
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, const std::string& path, int camera, GltfBudget& budget)
      : model_(model),
        path_(path),
        wanted_camera_(camera),
        budget_(budget),
        materials_(model, path, budget, scene_) {}

  // Printed only once the whole file is accepted, so a refused file stays one line.
  const std::vector<std::string>& warnings() const { return warnings_; }

  SceneDescription run() {
    check_buffers();
    check_lights();
    check_gltf_node_tree(model_, path_);
    const int scene_index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.empty()) fail(path_, "scenes", "none");
    if (scene_index >= static_cast<int>(model_.scenes.size()))
      fail(path_, "scene", std::to_string(scene_index));
    if (model_.nodes.size() > kMaxGltfNodes)
      fail(path_, "nodes", std::to_string(model_.nodes.size()));
    const std::vector<int>& roots = model_.scenes[static_cast<std::size_t>(scene_index)].nodes;
    charge_scene(roots);
    on_path_.assign(model_.nodes.size(), false);
    for (const int node : roots) visit_tree(node);
    if (positionless_primitives_ > 0) {
      warnings_.push_back(
          std::to_string(positionless_primitives_) +
          " primitive(s) without POSITION skipped (the first: " + first_positionless_ + ")");
    }
    scene_.name = std::filesystem::path(path_).stem().string();
    scene_.ambient = glm::vec3(0.0f);
    if (lights_.empty() && mesh_nodes_.empty() && scene_.directional_lights.empty()) {
      warnings_.push_back("nothing to render (no triangle meshes or lights in scene " +
                          std::to_string(scene_index) + "): the background only");
    }
    std::vector<SceneNode> children = std::move(lights_);
    for (SceneNode& mesh : mesh_nodes_) children.push_back(std::move(mesh));
    scene_.root = union_node(std::move(children));
    if (!has_camera_ && wanted_camera_ > 0) {
      fail(path_, "camera",
           std::to_string(wanted_camera_) + " (the file has " + std::to_string(cameras_seen_) +
               " cameras in its scene)");
    }
    scene_.camera = has_camera_ ? camera_ : framing_camera();
    for (std::string& line : materials_.warnings()) warnings_.push_back(std::move(line));
    return std::move(scene_);
  }

 private:
  // Every view and accessor lies inside its data, so a truncated .bin fails here, by name.
  void check_buffers() const {
    for (std::size_t i = 0; i < model_.bufferViews.size(); ++i) {
      const tinygltf::BufferView& view = model_.bufferViews[i];
      const std::string where = "bufferViews[" + std::to_string(i) + "]";
      if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
        fail(path_, where + ".buffer", std::to_string(view.buffer));
      }
      const std::size_t available =
          model_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
      if (view.byteOffset > available || view.byteLength > available - view.byteOffset) {
        fail(path_, where,
             "bytes " + std::to_string(view.byteOffset) + "+" + std::to_string(view.byteLength) +
                 " beyond the buffer's " + std::to_string(available));
      }
    }
    for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
      const tinygltf::Accessor& accessor = model_.accessors[i];
      const std::string where = "accessors[" + std::to_string(i) + "]";
      if (accessor.count > kMaxGltfAccessorElements)
        fail(path_, where + ".count", std::to_string(accessor.count));
      const int component_bytes =
          tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
      const int components =
          tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
      if (component_bytes <= 0 || components <= 0)
        fail(path_, where, "unknown component type or type");
      const auto element_bytes =
          static_cast<std::size_t>(component_bytes) * static_cast<std::size_t>(components);
      if (accessor.sparse.isSparse) check_sparse(accessor, where, element_bytes);
      if (accessor.bufferView < 0) continue;  // all zeros (or sparse only): no bytes to check
      if (static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) {
        fail(path_, where + ".bufferView", std::to_string(accessor.bufferView));
      }
      const tinygltf::BufferView& view =
          model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
      if (view.byteStride != 0 && view.byteStride < element_bytes) {
        fail(path_, where,
             "byteStride " + std::to_string(view.byteStride) + " below the element's " +
                 std::to_string(element_bytes) + " bytes");
      }
      const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
      check_span(where, accessor.byteOffset, stride, accessor.count, element_bytes,
                 view.byteLength);
    }
  }

  // byte_offset + stride * (count - 1) + element_bytes within view_bytes (none when count is 0).
  void check_span(const std::string& where, double byte_offset, std::size_t stride,
                  std::size_t count, std::size_t element_bytes, std::size_t view_bytes) const {
    if (count == 0) return;
    const double end_bytes = byte_offset +
                             static_cast<double>(stride) * static_cast<double>(count - 1) +
                             static_cast<double>(element_bytes);
    if (byte_offset < 0.0 || end_bytes > static_cast<double>(view_bytes)) {
      fail(path_, where,
           std::to_string(count) + " elements beyond the view's " + std::to_string(view_bytes) +
               " bytes");
    }
  }

  const tinygltf::BufferView& view_at(int index, const std::string& where) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.bufferViews.size())
      fail(path_, where + ".bufferView", std::to_string(index));
    return model_.bufferViews[static_cast<std::size_t>(index)];
  }

  void check_sparse(const tinygltf::Accessor& accessor, const std::string& where,
                    std::size_t element_bytes) const {
    const int count = accessor.sparse.count;
    if (count <= 0 || static_cast<std::size_t>(count) > accessor.count)
      fail(path_, where + ".sparse.count", std::to_string(count));
    const int index_bytes = tinygltf::GetComponentSizeInBytes(
        static_cast<std::uint32_t>(accessor.sparse.indices.componentType));
    const int index_type = accessor.sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      fail(path_, where + ".sparse.indices.componentType", std::to_string(index_type));
    const auto sparse_count = static_cast<std::size_t>(count);
    const tinygltf::BufferView& indices =
        view_at(accessor.sparse.indices.bufferView, where + ".sparse.indices");
    check_span(where + ".sparse.indices", accessor.sparse.indices.byteOffset,
               static_cast<std::size_t>(index_bytes), sparse_count,
               static_cast<std::size_t>(index_bytes), indices.byteLength);
    const tinygltf::BufferView& values =
        view_at(accessor.sparse.values.bufferView, where + ".sparse.values");
    check_span(where + ".sparse.values", accessor.sparse.values.byteOffset, element_bytes,
               sparse_count, element_bytes, values.byteLength);
  }

  void check_lights() const {
    for (std::size_t i = 0; i < model_.lights.size(); ++i) {
      const tinygltf::Light& light = model_.lights[i];
      const std::string where = "lights[" + std::to_string(i) + "]";
      if (!std::isfinite(light.intensity) || light.intensity < 0.0) {
        fail(path_, where + ".intensity", number_text(light.intensity));
      }
      if (!std::isfinite(light.range) || light.range < 0.0)
        fail(path_, where + ".range", number_text(light.range));
      if (!light.color.empty() && light.color.size() != 3) {
        fail(path_, where + ".color", std::to_string(light.color.size()) + " components");
      }
      for (const double c : light.color) {
        if (!std::isfinite(c) || c < 0.0) fail(path_, where + ".color", number_text(c));
      }
      if (light.type == "spot") {
        const double inner = light.spot.innerConeAngle;
        const double outer = light.spot.outerConeAngle;
        // The extension: 0 <= inner < outer <= PI/2.
        if (!std::isfinite(outer) || !(outer > 0.0) || outer > kPi / 2.0) {
          fail(path_, where + ".spot.outerConeAngle", number_text(outer));
        }
        if (!std::isfinite(inner) || inner < 0.0 || inner >= outer) {
          fail(path_, where + ".spot.innerConeAngle", number_text(inner));
        }
      } else if (light.type != "point" && light.type != "directional") {
        fail(path_, where + ".type", "'" + light.type + "'");
      }
    }
  }

  glm::dmat4 local_matrix(const tinygltf::Node& node, const std::string& where) const {
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16)
        fail(path_, where + ".matrix", std::to_string(node.matrix.size()) + " values");
      glm::dmat4 m(1.0);
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
          const double v = node.matrix[static_cast<std::size_t>(4 * c + r)];
          if (!std::isfinite(v)) fail(path_, where + ".matrix", number_text(v));
          m[c][r] = v;
        }
      }
      return m;
    }
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    auto read = [&](const std::vector<double>& values, std::size_t n, const char* key) {
      if (!values.empty() && values.size() != n)
        fail(path_, where + "." + key, std::to_string(values.size()) + " values");
      for (const double v : values) {
        if (!std::isfinite(v)) fail(path_, where + "." + key, number_text(v));
      }
      return !values.empty();
    };
    if (read(node.translation, 3, "translation"))
      t = {node.translation[0], node.translation[1], node.translation[2]};
    if (read(node.scale, 3, "scale")) s = {node.scale[0], node.scale[1], node.scale[2]};
    if (read(node.rotation, 4, "rotation")) {
      q = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1],
                     node.rotation[2]);  // glTF: x y z w
      const double length = glm::length(q);
      if (!(length > 0.0)) fail(path_, where + ".rotation", "zero quaternion");
      q = q / length;
    }
    return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), s);
  }

  int light_of(const tinygltf::Node& node, const std::string& where) const {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) return -1;
    const tinygltf::Value& index = ext->second.Get("light");
    if (!index.IsNumber()) fail(path_, where + ".extensions.KHR_lights_punctual.light", "missing");
    const double value = index.GetNumberAsDouble();
    if (!(value >= 0.0) || value >= static_cast<double>(model_.lights.size()) ||
        value != std::floor(value)) {
      fail(path_, where + ".extensions.KHR_lights_punctual.light", number_text(value));
    }
    return static_cast<int>(value);
  }

  // --- accessors (bounds checked in check_buffers) -------------------------------------------

  const unsigned char* view_bytes(const tinygltf::BufferView& view) const {
    return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
  }

  // One component as stored, integers exactly (a double holds every u32).
  static double raw_component(const unsigned char* at, int component_type) {
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return static_cast<double>(load<std::int8_t>(at));
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return static_cast<double>(load<std::uint8_t>(at));
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return static_cast<double>(load<std::int16_t>(at));
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return static_cast<double>(load<std::uint16_t>(at));
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return static_cast<double>(load<std::uint32_t>(at));
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return static_cast<double>(load<float>(at));
      default:
        return static_cast<double>(load<double>(at));
    }
  }

  // The spec's decoding of normalized integers: c / max, signed ones clamped at -1.
  static double normalized_component(double raw, int component_type) {
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(raw / 127.0, -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return raw / 255.0;
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(raw / 32767.0, -1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return raw / 65535.0;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return raw / 4294967295.0;
      default:
        return raw;
    }
  }

  // Every element's components, row after row: the view's stride applied, normalized integers
  // decoded, then the sparse substitutions. `types` lists the accessor types the caller takes.
  std::vector<double> read_accessor(int index, std::initializer_list<int> types,
                                    const std::string& where) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
      fail(path_, where, "accessor " + std::to_string(index));
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
    const std::string accessor_where = "accessors[" + std::to_string(index) + "]";
    if (std::find(types.begin(), types.end(), accessor.type) == types.end())
      fail(path_, accessor_where + ".type",
           "type " + std::to_string(accessor.type) + " where " + where + " needs another");
    const auto components = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type)));
    const auto component_bytes = static_cast<std::size_t>(
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType)));
    const int type = accessor.componentType;
    auto decode = [&](const unsigned char* at) {
      const double raw = raw_component(at, type);
      return accessor.normalized ? normalized_component(raw, type) : raw;
    };
    std::vector<double> values(accessor.count * components, 0.0);
    if (accessor.bufferView >= 0) {
      const tinygltf::BufferView& view =
          model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
      const std::size_t stride =
          view.byteStride != 0 ? view.byteStride : components * component_bytes;
      const unsigned char* base = view_bytes(view) + accessor.byteOffset;
      for (std::size_t e = 0; e < accessor.count; ++e) {
        for (std::size_t c = 0; c < components; ++c)
          values[e * components + c] = decode(base + e * stride + c * component_bytes);
      }
    }
    if (accessor.sparse.isSparse) {
      const auto& sparse = accessor.sparse;
      const tinygltf::BufferView& index_view =
          model_.bufferViews[static_cast<std::size_t>(sparse.indices.bufferView)];
      const tinygltf::BufferView& value_view =
          model_.bufferViews[static_cast<std::size_t>(sparse.values.bufferView)];
      const auto index_bytes = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(
          static_cast<std::uint32_t>(sparse.indices.componentType)));
      const unsigned char* indices = view_bytes(index_view) + sparse.indices.byteOffset;
      const unsigned char* replacements = view_bytes(value_view) + sparse.values.byteOffset;
      for (std::size_t k = 0; k < static_cast<std::size_t>(sparse.count); ++k) {
        const double target =
            raw_component(indices + k * index_bytes, sparse.indices.componentType);
        if (target >= static_cast<double>(accessor.count))
          fail(path_, accessor_where + ".sparse.indices",
               number_text(target) + " beyond the count " + std::to_string(accessor.count));
        const auto e = static_cast<std::size_t>(target);
        for (std::size_t c = 0; c < components; ++c) {
          values[e * components + c] =
              decode(replacements + (k * components + c) * component_bytes);
        }
      }
    }
    return values;
  }

  template <typename T>
  static T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof(T));
    return value;
  }

  // --- the memory budget (gltf_budget.h) ----------------------------------------------------

  // Charges, before anything is built, every mesh the scene's nodes draw and every texture their
  // materials sample. Nodes are walked with a stack of their own, each at most once.
  void charge_scene(const std::vector<int>& roots) {
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

  std::uint64_t accessor_count(int index) const {
    return index >= 0 && static_cast<std::size_t>(index) < model_.accessors.size()
               ? model_.accessors[static_cast<std::size_t>(index)].count
               : 0;
  }

  // Each triangle primitive as read_primitive builds it: its vertices read, the flat ones made
  // when it has no normals, and its triangles; an accessor counted again by every primitive.
  void charge_mesh(int index) {
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
                                std::to_string(p) + "] (" + std::to_string(built) +
                                " vertices and " + std::to_string(triangles) +
                                " triangles as built)";
      budget_.charge(built, kGltfBytesPerVertex, where);
      budget_.charge(triangles, kGltfBytesPerTriangle, where);
      materials_.charge_material(primitive.material);
    }
  }

  // --- meshes -----------------------------------------------------------------------------------

  static std::vector<glm::vec3> as_vec3(const std::vector<double>& values) {
    std::vector<glm::vec3> out(values.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[i] = glm::vec3(glm::dvec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]));
    }
    return out;
  }

  // The triangles a primitive's mode makes of its vertex list, as the spec numbers them: strip
  // triangle i is (i, i+1, i+2) for even i and (i, i+2, i+1) for odd i; fans share vertex 0.
  static std::vector<glm::uvec3> triangles_of_mode(const std::vector<std::uint32_t>& v, int mode) {
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

  renderer::TriangleMesh read_primitive(const tinygltf::Primitive& primitive,
                                        const std::string& where) {
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end())
      fail(path_, where + ".attributes.POSITION", "missing");
    renderer::TriangleMesh part;
    part.positions = as_vec3(
        read_accessor(position->second, {TINYGLTF_TYPE_VEC3}, where + ".attributes.POSITION"));
    const auto vertex_count = part.positions.size();
    std::vector<std::uint32_t> vertices;
    if (primitive.indices >= 0) {
      const std::string indices_where = where + ".indices";
      if (static_cast<std::size_t>(primitive.indices) < model_.accessors.size()) {
        const int type =
            model_.accessors[static_cast<std::size_t>(primitive.indices)].componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
          fail(path_, indices_where, "component type " + std::to_string(type));
      }
      for (const double index :
           read_accessor(primitive.indices, {TINYGLTF_TYPE_SCALAR}, indices_where)) {
        if (index >= static_cast<double>(vertex_count))
          fail(path_, indices_where,
               "vertex " + number_text(index) + " of " + std::to_string(vertex_count));
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
          read_accessor(uv->second, {TINYGLTF_TYPE_VEC2}, where + ".attributes.TEXCOORD_0");
      if (values.size() != 2 * vertex_count)
        fail(path_, where + ".attributes.TEXCOORD_0",
             std::to_string(values.size() / 2) + " for " + std::to_string(vertex_count) +
                 " vertices");
      for (std::size_t i = 0; i < vertex_count; ++i)
        part.uvs.emplace_back(static_cast<float>(values[2 * i]),
                              static_cast<float>(values[2 * i + 1]));
    }
    if (normal != primitive.attributes.end()) {
      part.normals = as_vec3(
          read_accessor(normal->second, {TINYGLTF_TYPE_VEC3}, where + ".attributes.NORMAL"));
      if (part.normals.size() != vertex_count)
        fail(path_, where + ".attributes.NORMAL",
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
  std::uint32_t scene_mesh(int index, const std::string& where) {
    if (index >= static_cast<int>(model_.meshes.size()))
      fail(path_, where + ".mesh", std::to_string(index));
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
        fail(path_, primitive_where + ".mode", std::to_string(primitive.mode));
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
      slot = kNoIndex;
      return slot;
    }
    glm::vec3 lo(std::numeric_limits<float>::infinity()),
        hi(-std::numeric_limits<float>::infinity());
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

  // A node drawing a mesh: a similarity placement of the mesh's one master when the node's world
  // matrix is one (the usual case: every such node shares one Embree prototype); otherwise a
  // master per distinct linear part, with that part baked in, placed by the translation.
  void place_mesh(int gltf_mesh, const glm::dmat4& world, const std::string& where) {
    const glm::dmat3 linear(world);
    const glm::dvec3 translation(world[3]);
    const double det = glm::determinant(linear);
    if (!std::isfinite(det)) fail(path_, where, "transform of a mesh " + number_text(det));
    // A scale of 0 (on any axis) is how authors hide a node: the mesh has no area to draw.
    if (!(std::abs(det) > 1e-18)) return;
    const std::uint32_t mesh = scene_mesh(gltf_mesh, where);
    if (mesh == kNoIndex) return;
    const double scale = std::cbrt(std::abs(det));
    const glm::dmat3 unit = linear / scale;
    const glm::dmat3 gram = glm::transpose(unit) * unit;
    double off_orthonormal = 0.0;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r)
        off_orthonormal = std::max(off_orthonormal, std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)));
    }
    Affine place;
    place.translate = glm::vec3(translation);
    glm::mat3 baked(1.0f);
    if (det > 0.0 && off_orthonormal < 1e-6) {
      place.scale = static_cast<float>(scale);
      const glm::dquat rotation = glm::normalize(glm::quat_cast(unit));
      const double angle = glm::angle(rotation);
      if (angle > 0.0) {
        place.rotate_axis = glm::vec3(glm::axis(rotation));
        place.rotate_degrees = static_cast<float>(angle * 180.0 / kPi);
      }
    } else {
      baked = glm::mat3(linear);
    }
    const std::uint32_t master = mesh_master(mesh, baked);
    mesh_nodes_.push_back(affine_node(place, instance_node(master)));
    const auto& [lo, hi] = mesh_bounds_[mesh];
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 local(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                             corner & 4 ? hi.z : lo.z);
      const glm::dvec3 p = glm::dvec3(world * glm::dvec4(local, 1.0));
      lo_ = glm::min(lo_, p);
      hi_ = glm::max(hi_, p);
    }
  }

  std::uint32_t mesh_master(std::uint32_t mesh, const glm::mat3& linear) {
    std::array<float, 9> key_linear{};
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) key_linear[static_cast<std::size_t>(3 * c + r)] = linear[c][r];
    }
    const auto key = std::make_pair(mesh, key_linear);
    const auto found = master_of_.find(key);
    if (found != master_of_.end()) return found->second;
    const std::string name =
        "mesh " + std::to_string(mesh) + " '" + scene_.meshes[mesh].name + "'" +
        (linear == glm::mat3(1.0f) ? std::string()
                                   : " deformed " + std::to_string(master_of_.size()));
    const std::uint32_t master = add_master(scene_, name, mesh_node(mesh, linear));
    master_of_.emplace(key, master);
    return master;
  }

  // Depth first, in the file's order, with a stack of its own: a tree 10,000 nodes deep costs a
  // vector, not the call stack.
  void visit_tree(int root) {
    struct Frame {
      int node;
      glm::dmat4 world;
      std::size_t next_child;
    };
    std::vector<Frame> stack;
    stack.push_back({root, enter_node(root, glm::dmat4(1.0)), 0});
    while (!stack.empty()) {
      Frame& top = stack.back();
      const std::vector<int>& children = model_.nodes[static_cast<std::size_t>(top.node)].children;
      if (top.next_child < children.size()) {
        const int child = children[top.next_child++];
        const glm::dmat4 world = enter_node(child, top.world);
        stack.push_back({child, world, 0});
      } else {
        on_path_[static_cast<std::size_t>(top.node)] = false;
        stack.pop_back();
      }
    }
  }

  // Reads one node under its parent's world matrix and returns its own; the node stays on the
  // path (for the cycle check) until visit_tree has visited its children.
  glm::dmat4 enter_node(int index, const glm::dmat4& parent) {
    if (index < 0 || index >= static_cast<int>(model_.nodes.size()))
      fail(path_, "node", std::to_string(index));
    const std::string where = "nodes[" + std::to_string(index) + "]";
    if (on_path_[static_cast<std::size_t>(index)]) fail(path_, where, "cycle in the node tree");
    if (++visits_ > kMaxGltfNodes)
      fail(path_, where, "more than " + std::to_string(kMaxGltfNodes) + " node visits");
    on_path_[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * local_matrix(node, where);
    const glm::dvec3 position(world[3]);
    // A glTF light and camera use the node's rotation only: the direction is the transformed -Z.
    const glm::dvec3 forward = -glm::dvec3(world[2]);
    const int light = light_of(node, where);
    if (light >= 0)
      add_light(model_.lights[static_cast<std::size_t>(light)], position, forward, where);
    if (node.camera >= 0) add_camera(node, world, where);
    if (node.mesh >= 0) place_mesh(node.mesh, world, where);
    return world;
  }

  void add_light(const tinygltf::Light& light, const glm::dvec3& position,
                 const glm::dvec3& forward, const std::string& where) {
    double length = glm::length(forward);
    if (!std::isfinite(length)) fail(path_, where, "transform of a light " + number_text(length));
    glm::dvec3 axis_forward = forward;
    if (!(length > 0.0)) {
      // A zero scale leaves no direction; a point light needs none (glTF never scales a light).
      if (light.type != "point") {
        warnings_.push_back(where + ": " + light.type +
                            " light under a zero scale has no direction; skipped");
        return;
      }
      axis_forward = {0.0, 0.0, -1.0};
      length = 1.0;
    }
    glm::dvec3 colour(1.0);
    if (light.color.size() == 3) colour = {light.color[0], light.color[1], light.color[2]};
    // glTF: candela for point and spot lights, lux for directional ones, used as authored: levrt's
    // irradiance at distance 1 (or everywhere). The exposure, not the scene, brings it to the
    // display (renderer/display_transform.h).
    const glm::vec3 intensity(colour * light.intensity);
    const glm::dvec3 direction = axis_forward / length;
    if (light.type == "directional") {
      scene_.directional_lights.push_back({glm::vec3(direction), intensity});
      return;
    }
    Affine place;
    place.translate = glm::vec3(position);
    // The rotation carrying levrt's spot axis -Z onto the light's world direction.
    const glm::dvec3 axis = glm::cross(glm::dvec3(0.0, 0.0, -1.0), direction);
    const double cosine = glm::clamp(-direction.z, -1.0, 1.0);
    if (glm::length(axis) > 1e-12) {
      place.rotate_axis = glm::vec3(glm::normalize(axis));
      place.rotate_degrees = static_cast<float>(std::acos(cosine) * 180.0 / kPi);
    } else if (cosine < 0.0) {
      place.rotate_axis = {1.0f, 0.0f, 0.0f};
      place.rotate_degrees = 180.0f;
    }
    // The extension: range 0 or absent is infinite.
    const float range = light.range > 0.0 ? static_cast<float>(light.range)
                                          : std::numeric_limits<float>::infinity();
    if (light.type == "point") {
      SceneNode node = point_light_node(intensity);
      std::get<PointLightSource>(node.data).range = range;
      lights_.push_back(affine_node(place, std::move(node)));
    } else {
      SceneNode node = spot_light_node(
          intensity, static_cast<float>(light.spot.outerConeAngle * 180.0 / kPi), 0.0f);
      auto& spot = std::get<SpotLightSource>(node.data);
      spot.range = range;
      spot.inner_cone_degrees = static_cast<float>(light.spot.innerConeAngle * 180.0 / kPi);
      lights_.push_back(affine_node(place, std::move(node)));
    }
    lo_ = glm::min(lo_, position);
    hi_ = glm::max(hi_, position);
  }

  void add_camera(const tinygltf::Node& node, const glm::dmat4& world, const std::string& where) {
    if (has_camera_) return;
    if (node.camera >= static_cast<int>(model_.cameras.size()))
      fail(path_, where + ".camera", std::to_string(node.camera));
    const tinygltf::Camera& camera = model_.cameras[static_cast<std::size_t>(node.camera)];
    const std::string camera_where = "cameras[" + std::to_string(node.camera) + "]";
    const bool orthographic = camera.type == "orthographic";
    if (camera.type != "perspective" && !orthographic) return;
    const double yfov = camera.perspective.yfov;
    if (!orthographic && (!std::isfinite(yfov) || !(yfov > 0.0) || yfov >= kPi))
      fail(path_, where + ".camera.yfov", number_text(yfov));
    // glTF's ymag is the half height seen (a negative one, which the spec advises against, as
    // its magnitude); the width follows the image's aspect ratio, as a perspective camera's does
    // (xmag, like aspectRatio, is not read: scenes/README.md).
    const double ymag = std::abs(camera.orthographic.ymag);
    if (orthographic && (!std::isfinite(ymag) || !(ymag > 0.0) || !(ymag < 1e30)))
      fail(path_, camera_where + ".orthographic.ymag", number_text(ymag));
    // --camera N: the N-th camera met in the node tree, depth first.
    if (cameras_seen_++ != wanted_camera_) return;
    const glm::dvec3 position(world[3]);
    const glm::dvec3 forward = -glm::dvec3(world[2]);
    const glm::dvec3 up(world[1]);
    if (!std::isfinite(glm::length(forward) + glm::length(up)))
      fail(path_, where, "camera transform not finite");
    if (!(glm::length(forward) > 0.0) || !(glm::length(up) > 0.0)) {
      warnings_.push_back(where + ": camera under a zero scale has no direction; not used");
      return;
    }
    camera_.position = glm::vec3(position);
    camera_.target = glm::vec3(position + glm::normalize(forward));
    camera_.up = glm::vec3(glm::normalize(up));
    if (orthographic) {
      camera_.orthographic_half_height = static_cast<float>(ymag);
    } else {
      camera_.vertical_fov_deg = static_cast<float>(yfov * 180.0 / kPi);
    }
    has_camera_ = true;
  }

  // From the front (+Z) and above (+Y, glTF's up), far enough to see the lights' bounds.
  renderer::Camera framing_camera() const {
    renderer::Camera camera;
    glm::dvec3 centre(0.0);
    double radius = 1.0;  // a single point (or nothing): a unit sphere around it
    if (lo_.x <= hi_.x) {
      centre = 0.5 * (lo_ + hi_);
      const double half_diagonal = 0.5 * glm::length(hi_ - lo_);
      if (half_diagonal > 0.0) radius = half_diagonal;
    }
    // The bounding sphere fits the vertical field of view, seen 31 degrees from above.
    const double half_fov = 0.5 * static_cast<double>(camera.vertical_fov_deg) * kPi / 180.0;
    const double distance = radius / std::sin(half_fov);
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.target = glm::vec3(centre);
    camera.position = glm::vec3(centre + distance * glm::normalize(glm::dvec3(0.0, 0.6, 1.0)));
    return camera;
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  int wanted_camera_;
  GltfBudget& budget_;
  int cameras_seen_ = 0;
  std::vector<bool> on_path_;
  std::size_t visits_ = 0;
  std::vector<SceneNode> lights_;
  std::vector<std::string> warnings_;
  bool has_camera_ = false;
  static constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kUnconverted = kNoIndex - 1;
  SceneDescription scene_;
  GltfMaterials materials_;             // adds the materials and textures to scene_
  std::vector<std::uint32_t> mesh_of_;  // per glTF mesh: its scene mesh
  std::vector<bool> charged_meshes_;    // per glTF mesh: charged to the budget
  std::vector<std::pair<glm::vec3, glm::vec3>> mesh_bounds_;  // per scene mesh, in its frame
  std::map<std::pair<std::uint32_t, std::array<float, 9>>, std::uint32_t> master_of_;
  std::vector<SceneNode> mesh_nodes_;
  std::size_t positionless_primitives_ = 0;
  std::string first_positionless_;  // the glTF path of the first one, for the warning
  renderer::Camera camera_;
  glm::dvec3 lo_{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi_{-std::numeric_limits<double>::infinity()};
};

bool ends_with(std::string_view name, std::string_view suffix) {
  return name.size() > suffix.size() && name.substr(name.size() - suffix.size()) == suffix;
}

}  // namespace

bool is_gltf_file_name(std::string_view name) {
  return ends_with(name, ".gltf") || ends_with(name, ".glb");
}

SceneDescription parse_gltf_scene(const std::string& bytes, const std::string& path, int camera,
                                  std::uint64_t budget_bytes) {
  if (camera < 0) fail(path, "camera", std::to_string(camera));
  GltfBudget budget(path, budget_bytes);
  const bool binary = is_glb(bytes);
  FolderReader reader;
  reader.gltf_path = path;
  reader.folder = std::filesystem::path(path).parent_path().string();
  GltfDocumentFacts document = check_gltf_document(bytes, binary, path, reader.folder, budget);
  reader.files = std::move(document.files);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_encoded_image, nullptr);
  loader.SetFsCallbacks({accept_any_name, keep_name, read_checked_file, write_nothing, &reader});
  tinygltf::Model model;
  std::string error, loader_warning;
  // No base folder: tinygltf hands the decoded URI itself to read_checked_file, which reads it
  // from reader.folder only if check_gltf_document approved it.
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &error, &loader_warning,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()), "")
             : loader.LoadASCIIFromString(&model, &error, &loader_warning, bytes.data(),
                                          static_cast<unsigned int>(bytes.size()), "");
  if (!reader.error.empty()) throw std::invalid_argument(reader.error);
  // tinygltf turns the exceptions of its JSON parser into an error text; running out of memory
  // is no fault of the file (exit 1, not 2), so it goes on as what it was.
  if (!ok && error == std::bad_alloc().what()) throw std::bad_alloc();
  if (!ok)
    fail(path, "not a readable glTF file", error.empty() ? "(no detail)" : first_line(error));
  Importer importer(model, path, camera, budget);
  SceneDescription scene = importer.run();
  // The limits every scene obeys (light count, intensities), with the file's name in front.
  try {
    validate_description(scene);
  } catch (const std::invalid_argument& e) {
    fail(path, "scene", e.what());
  }
  std::vector<std::string> warnings = importer.warnings();
  if (!document.ignored_extensions.empty()) {
    std::string names;
    for (const std::string& name : document.ignored_extensions)
      names += (names.empty() ? "" : ", ") + escape_control_characters(name);
    warnings.insert(warnings.begin(), "extensionsUsed: " + names + " ignored (levrt honours " +
                                          honoured_gltf_extensions_text() + ")");
  }
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "%s: warning: %s\n", path.c_str(), warning.c_str());
  }
  return scene;
}

}  // namespace scenes
