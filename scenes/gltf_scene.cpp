#include "scenes/gltf_scene.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/scene_instantiation.h"

namespace scenes {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number_text(double value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

[[noreturn]] void fail(const std::string& path, const std::string& what, const std::string& value) {
  throw std::invalid_argument(path + ": " + what + ": " + value);
}

std::string first_line(const std::string& text) {
  const std::size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

// Images are never decoded: only material factors are used.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

class Importer {
 public:
  Importer(const tinygltf::Model& model, const std::string& path, float light_scale)
      : model_(model), path_(path), light_scale_(light_scale) {}

  // Printed only once the whole file is accepted, so a refused file stays one line.
  const std::vector<std::string>& warnings() const { return warnings_; }

  SceneDescription run() {
    check_buffers();
    check_lights();
    const int scene_index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.empty()) fail(path_, "scenes", "none");
    if (scene_index >= static_cast<int>(model_.scenes.size()))
      fail(path_, "scene", std::to_string(scene_index));
    if (model_.nodes.size() > kMaxGltfNodes)
      fail(path_, "nodes", std::to_string(model_.nodes.size()));
    on_path_.assign(model_.nodes.size(), false);
    for (const int node : model_.scenes[static_cast<std::size_t>(scene_index)].nodes)
      visit(node, glm::dmat4(1.0));
    SceneDescription scene;
    scene.name = std::filesystem::path(path_).stem().string();
    scene.ambient = glm::vec3(0.0f);
    scene.root = union_node(std::move(lights_));
    scene.camera = has_camera_ ? camera_ : framing_camera();
    return scene;
  }

 private:
  // Every view and accessor lies inside its data, so a truncated .bin fails here, by name.
  void check_buffers() const {
    for (std::size_t i = 0; i < model_.bufferViews.size(); ++i) {
      const tinygltf::BufferView& view = model_.bufferViews[i];
      const std::string where = "bufferViews[" + std::to_string(i) + "]";
      if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
        fail(path_, where + "/buffer", std::to_string(view.buffer));
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
      if (accessor.bufferView < 0) continue;  // all zeros (or sparse only): no bytes to check
      if (static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) {
        fail(path_, where + "/bufferView", std::to_string(accessor.bufferView));
      }
      const tinygltf::BufferView& view =
          model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
      const int component_bytes =
          tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
      const int components =
          tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
      if (component_bytes <= 0 || components <= 0)
        fail(path_, where, "unknown component type or type");
      const auto element_bytes =
          static_cast<std::size_t>(component_bytes) * static_cast<std::size_t>(components);
      const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
      if (accessor.count == 0) continue;
      const double end_bytes =
          static_cast<double>(accessor.byteOffset) +
          static_cast<double>(stride) * static_cast<double>(accessor.count - 1) +
          static_cast<double>(element_bytes);
      if (end_bytes > static_cast<double>(view.byteLength)) {
        fail(path_, where,
             number_text(accessor.count) + " elements beyond the view's " +
                 std::to_string(view.byteLength) + " bytes");
      }
    }
  }

  void check_lights() const {
    for (std::size_t i = 0; i < model_.lights.size(); ++i) {
      const tinygltf::Light& light = model_.lights[i];
      const std::string where = "lights[" + std::to_string(i) + "]";
      if (!std::isfinite(light.intensity) || light.intensity < 0.0) {
        fail(path_, where + "/intensity", number_text(light.intensity));
      }
      if (!std::isfinite(light.range) || light.range < 0.0)
        fail(path_, where + "/range", number_text(light.range));
      if (!light.color.empty() && light.color.size() != 3) {
        fail(path_, where + "/color", std::to_string(light.color.size()) + " components");
      }
      for (const double c : light.color) {
        if (!std::isfinite(c) || c < 0.0) fail(path_, where + "/color", number_text(c));
      }
      if (light.type == "spot") {
        const double inner = light.spot.innerConeAngle;
        const double outer = light.spot.outerConeAngle;
        // The extension: 0 <= inner < outer <= PI/2.
        if (!std::isfinite(outer) || !(outer > 0.0) || outer > kPi / 2.0) {
          fail(path_, where + "/spot/outerConeAngle", number_text(outer));
        }
        if (!std::isfinite(inner) || inner < 0.0 || inner >= outer) {
          fail(path_, where + "/spot/innerConeAngle", number_text(inner));
        }
      } else if (light.type != "point" && light.type != "directional") {
        fail(path_, where + "/type", "'" + light.type + "'");
      }
    }
  }

  glm::dmat4 local_matrix(const tinygltf::Node& node, const std::string& where) const {
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16)
        fail(path_, where + "/matrix", std::to_string(node.matrix.size()) + " values");
      glm::dmat4 m(1.0);
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
          const double v = node.matrix[static_cast<std::size_t>(4 * c + r)];
          if (!std::isfinite(v)) fail(path_, where + "/matrix", number_text(v));
          m[c][r] = v;
        }
      }
      return m;
    }
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    auto read = [&](const std::vector<double>& values, std::size_t n, const char* key) {
      if (!values.empty() && values.size() != n)
        fail(path_, where + "/" + key, std::to_string(values.size()) + " values");
      for (const double v : values) {
        if (!std::isfinite(v)) fail(path_, where + "/" + key, number_text(v));
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
      if (!(length > 0.0)) fail(path_, where + "/rotation", "zero quaternion");
      q = q / length;
    }
    return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), s);
  }

  int light_of(const tinygltf::Node& node, const std::string& where) const {
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) return -1;
    const tinygltf::Value& index = ext->second.Get("light");
    if (!index.IsNumber()) fail(path_, where + "/extensions/KHR_lights_punctual/light", "missing");
    const double value = index.GetNumberAsDouble();
    if (!(value >= 0.0) || value >= static_cast<double>(model_.lights.size()) ||
        value != std::floor(value)) {
      fail(path_, where + "/extensions/KHR_lights_punctual/light", number_text(value));
    }
    return static_cast<int>(value);
  }

  void visit(int index, const glm::dmat4& parent) {
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
    if (node.mesh >= 0 && !warned_mesh_) {
      warned_mesh_ = true;
      const std::string name = node.mesh < static_cast<int>(model_.meshes.size())
                                   ? model_.meshes[static_cast<std::size_t>(node.mesh)].name
                                   : std::string();
      warnings_.push_back("triangle meshes are not imported (first: mesh " +
                          std::to_string(node.mesh) + " '" + name + "')");
    }
    for (const int child : node.children) visit(child, world);
    on_path_[static_cast<std::size_t>(index)] = false;
  }

  void add_light(const tinygltf::Light& light, const glm::dvec3& position,
                 const glm::dvec3& forward, const std::string& where) {
    if (light.type == "directional") {
      warnings_.push_back("directional light '" + light.name + "' is not imported");
      return;
    }
    const double length = glm::length(forward);
    if (!(length > 0.0) || !std::isfinite(length))
      fail(path_, where, "degenerate transform of a light");
    glm::dvec3 colour(1.0);
    if (light.color.size() == 3) colour = {light.color[0], light.color[1], light.color[2]};
    const glm::vec3 intensity(colour * light.intensity * static_cast<double>(light_scale_));
    const glm::dvec3 direction = forward / length;
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
    if (light.range > 0.0 && !warned_range_) {
      warned_range_ = true;
      warnings_.push_back("range of light '" + light.name + "' and any other is not applied (" +
                          number_text(light.range) + ")");
    }
    if (light.type == "point") {
      lights_.push_back(affine_node(place, point_light_node(intensity)));
    } else {
      if (!warned_falloff_) {
        warned_falloff_ = true;
        warnings_.push_back(
            "spot light '" + light.name +
            "' and any other: a hard cone at outerConeAngle, no falloff from innerConeAngle");
      }
      const auto cone_degrees = static_cast<float>(light.spot.outerConeAngle * 180.0 / kPi);
      lights_.push_back(affine_node(place, spot_light_node(intensity, cone_degrees, 0.0f)));
    }
    lo_ = glm::min(lo_, position);
    hi_ = glm::max(hi_, position);
  }

  void add_camera(const tinygltf::Node& node, const glm::dmat4& world, const std::string& where) {
    if (has_camera_) return;
    if (node.camera >= static_cast<int>(model_.cameras.size()))
      fail(path_, where + "/camera", std::to_string(node.camera));
    const tinygltf::Camera& camera = model_.cameras[static_cast<std::size_t>(node.camera)];
    if (camera.type != "perspective") return;
    const double yfov = camera.perspective.yfov;
    if (!std::isfinite(yfov) || !(yfov > 0.0) || yfov >= kPi)
      fail(path_, where + "/camera/yfov", number_text(yfov));
    const glm::dvec3 position(world[3]);
    const glm::dvec3 forward = -glm::dvec3(world[2]);
    const glm::dvec3 up(world[1]);
    if (!(glm::length(forward) > 0.0) || !(glm::length(up) > 0.0))
      fail(path_, where, "degenerate camera transform");
    camera_.position = glm::vec3(position);
    camera_.target = glm::vec3(position + glm::normalize(forward));
    camera_.up = glm::vec3(glm::normalize(up));
    camera_.vertical_fov_deg = static_cast<float>(yfov * 180.0 / kPi);
    has_camera_ = true;
  }

  // From the front (+Z) and above (+Y, glTF's up), far enough to see the lights' bounds.
  renderer::Camera framing_camera() const {
    renderer::Camera camera;
    glm::dvec3 centre(0.0);
    double radius = 1.0;
    if (lo_.x <= hi_.x) {
      centre = 0.5 * (lo_ + hi_);
      radius = std::max(1.0, 0.5 * glm::length(hi_ - lo_));
    }
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.target = glm::vec3(centre);
    camera.position = glm::vec3(centre + radius * glm::dvec3(0.0, 1.5, 2.5));
    return camera;
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  float light_scale_;
  std::vector<bool> on_path_;
  std::size_t visits_ = 0;
  std::vector<SceneNode> lights_;
  std::vector<std::string> warnings_;
  bool has_camera_ = false;
  bool warned_mesh_ = false;
  bool warned_range_ = false;
  bool warned_falloff_ = false;
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

SceneDescription parse_gltf_scene(const std::string& bytes, const std::string& path,
                                  float light_scale) {
  if (!std::isfinite(light_scale) || light_scale < 0.0f)
    fail(path, "light scale", number_text(light_scale));
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  tinygltf::Model model;
  std::string error, loader_warning;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const bool ok =
      ends_with(path, ".glb")
          ? loader.LoadBinaryFromMemory(&model, &error, &loader_warning,
                                        reinterpret_cast<const unsigned char*>(bytes.data()),
                                        static_cast<unsigned int>(bytes.size()), base_dir)
          : loader.LoadASCIIFromString(&model, &error, &loader_warning, bytes.data(),
                                       static_cast<unsigned int>(bytes.size()), base_dir);
  if (!ok)
    fail(path, "not a readable glTF file", error.empty() ? "(no detail)" : first_line(error));
  Importer importer(model, path, light_scale);
  SceneDescription scene = importer.run();
  // The limits every scene obeys (light count, intensities), with the file's name in front.
  try {
    validate_description(scene);
  } catch (const std::invalid_argument& e) {
    fail(path, "scene", e.what());
  }
  for (const std::string& warning : importer.warnings()) {
    std::fprintf(stderr, "%s: warning: %s\n", path.c_str(), warning.c_str());
  }
  return scene;
}

}  // namespace scenes
