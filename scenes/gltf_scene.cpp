#include "scenes/gltf_scene.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
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
#include "scenes/gltf_lights.h"
#include "scenes/gltf_materials.h"
#include "scenes/gltf_meshes.h"
#include "scenes/gltf_node_tree.h"
#include "scenes/gltf_refusal.h"
#include "scenes/gltf_schema.h"
#include "scenes/scene_file.h"
#include "scenes/scene_folder.h"
#include "scenes/scene_instantiation.h"
#include "scenes/scene_validation.h"

namespace scenes {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number_text(double value) {
  return gltf_number_text(value);
}

[[noreturn]] void fail(const std::string& path, const std::string& what, const std::string& value) {
  fail_gltf(path, what, value);
}

// `v`, or where its squared length overflows or underflows a double (a node scale of 1e200 or
// 1e-300, which still leaves the direction a light or camera needs), `v` divided by its largest
// component, so that its length can be taken. Zero stays zero (a node of scale 0); a vector that
// is not finite stays so.
glm::dvec3 measurable(const glm::dvec3& v) {
  const double length_squared = glm::dot(v, v);
  if (length_squared >= DBL_MIN && length_squared <= DBL_MAX) return v;
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!std::isfinite(largest) || !(largest > 0.0)) return v;
  return v / largest;
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
        materials_(model, path, budget, scene_),
        meshes_(model, path, budget, materials_, scene_, warnings_) {}

  // Printed only once the whole file is accepted, so a refused file stays one line.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // The glTF node each child of the description's root was placed for, with what it is ("nodes[3]
  // light"), in the root's order: lights, then meshes.
  std::vector<std::string> root_child_places() const {
    std::vector<std::string> places = light_places_;
    places.insert(places.end(), mesh_places_.begin(), mesh_places_.end());
    return places;
  }
  // The node of the file's camera the scene uses ("nodes[4] camera"), or "" for a framing one.
  const std::string& camera_place() const { return camera_place_; }

  SceneDescription run() {
    meshes_.check_buffers();
    check_gltf_lights(model_, path_);
    check_gltf_node_tree(model_, path_);
    const int scene_index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (model_.scenes.empty()) fail(path_, "scenes", "none");
    if (scene_index >= static_cast<int>(model_.scenes.size()))
      fail(path_, "scene", std::to_string(scene_index));
    if (model_.nodes.size() > kMaxGltfNodes)
      fail(path_, "nodes", std::to_string(model_.nodes.size()));
    const std::vector<int>& roots = model_.scenes[static_cast<std::size_t>(scene_index)].nodes;
    meshes_.charge_scene(roots);
    on_path_.assign(model_.nodes.size(), false);
    for (const int node : roots) visit_tree(node);
    if (meshes_.positionless_primitives() > 0) {
      warnings_.push_back(std::to_string(meshes_.positionless_primitives()) +
                          " primitive(s) without POSITION skipped (the first: " +
                          meshes_.first_positionless() + ")");
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
      // An affine transform, as glTF's matrices are (decomposable into TRS): a last row other
      // than 0, 0, 0, 1 is a projection, which the placement below would drop without a word.
      const glm::dvec4 last_row(m[0][3], m[1][3], m[2][3], m[3][3]);
      if (glm::length(last_row - glm::dvec4(0.0, 0.0, 0.0, 1.0)) > 1e-6) {
        fail(path_, where + ".matrix",
             "last row " + number_text(last_row.x) + ", " + number_text(last_row.y) + ", " +
                 number_text(last_row.z) + ", " + number_text(last_row.w) +
                 " (an affine matrix's is 0, 0, 0, 1)");
      }
      for (int c = 0; c < 3; ++c) m[c][3] = 0.0;
      m[3][3] = 1.0;
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

  // A node drawing a mesh: a similarity placement of the mesh's one master when the node's world
  // matrix is one (the usual case: every such node shares one Embree prototype); otherwise a
  // master per distinct linear part, with that part baked in, placed by the translation.
  void place_mesh(int gltf_mesh, const glm::dmat4& world, const std::string& where) {
    const glm::dmat3 linear(world);
    const glm::dvec3 translation(world[3]);
    const double det = glm::determinant(linear);
    if (!std::isfinite(det)) fail(path_, where, "transform of a mesh " + number_text(det));
    // A scale of 0 (on any axis) is how authors hide a node: the mesh has no area to draw. Below
    // the determinant a mesh placement may have (scene_validation.h; a scale of 1e-6), the mesh is
    // left out too, saying so.
    if (!(std::abs(det) > 1e-18)) {
      if (det != 0.0) {
        warnings_.push_back(where + ": mesh under a transform of determinant " + number_text(det) +
                            ", below the 1e-18 levrt draws (a scale of 1e-6); skipped");
      }
      return;
    }
    const std::uint32_t mesh = meshes_.scene_mesh(gltf_mesh, where);
    if (mesh == GltfMeshes::kNoMesh) return;
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
    mesh_places_.push_back(where + " mesh");
    const auto& [lo, hi] = meshes_.bounds(mesh);
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
    const int light = gltf_light_of(model_, node, path_, where);
    if (light >= 0)
      add_light(model_.lights[static_cast<std::size_t>(light)], position, forward, where);
    if (node.camera >= 0) add_camera(node, world, where);
    if (node.mesh >= 0) place_mesh(node.mesh, world, where);
    return world;
  }

  void add_light(const tinygltf::Light& light, const glm::dvec3& position,
                 const glm::dvec3& forward, const std::string& where) {
    glm::dvec3 axis_forward = measurable(forward);
    double length = glm::length(axis_forward);
    if (!std::isfinite(length)) fail(path_, where, "transform of a light " + number_text(length));
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
    lights_.push_back(gltf_light_node(light, intensity, position, direction));
    light_places_.push_back(where + " light");
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
    // glTF asks only for yfov above 0; a view of pi radians or more has no image plane.
    if (!orthographic && (!std::isfinite(yfov) || !(yfov > 0.0) || yfov >= kPi)) {
      fail(path_, camera_where + ".perspective.yfov",
           number_text(yfov) + " (a vertical field of view above 0 and below pi is expected)");
    }
    // glTF's ymag is the half height seen (a negative one, which the spec advises against, as
    // its magnitude); the width follows the image's aspect ratio, as a perspective camera's does
    // (xmag, like aspectRatio, is not read: scenes/README.md).
    // Bounded like any length of a scene (kMaxCoordinate): rays start up to ymag times the
    // aspect ratio from the camera, and Embree refuses (asserts on) origins past about 1.8e18.
    const double ymag = std::abs(camera.orthographic.ymag);
    if (orthographic && (!std::isfinite(ymag) || !(ymag > 0.0) || !(ymag <= kMaxCoordinate))) {
      fail(path_, camera_where + ".orthographic.ymag",
           number_text(ymag) + " (a half height in (0, " + number_text(kMaxCoordinate) + "])");
    }
    // --camera N: the N-th camera met in the node tree, depth first.
    if (cameras_seen_++ != wanted_camera_) return;
    const glm::dvec3 position(world[3]);
    const glm::dvec3 forward = measurable(-glm::dvec3(world[2]));
    const glm::dvec3 up = measurable(glm::dvec3(world[1]));
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
    camera_place_ = where + " camera";
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
    const glm::dvec3 position = centre + distance * glm::normalize(glm::dvec3(0.0, 0.6, 1.0));
    // Meshes or lights too far out for a view of them to stand where a scene's coordinates may
    // (kMaxCoordinate): refused by what they reach, not by the camera the file does not have.
    const auto within = [](const glm::dvec3& v) {
      return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
             std::abs(v.z) <= kMaxCoordinate;
    };
    if (!within(position) || !within(centre)) {
      const auto text = [](const glm::dvec3& v) {
        return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
      };
      fail(path_, "camera",
           "none in the file, and its meshes and lights reach from " + text(lo_) + " to " +
               text(hi_) + ": a view of them would stand at " + text(position) + ", beyond the " +
               number_text(kMaxCoordinate) + " a coordinate may have");
    }
    camera.position = glm::vec3(position);
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
  std::vector<std::string> light_places_, mesh_places_;  // root_child_places()
  std::string camera_place_;
  std::vector<std::string> warnings_;
  bool has_camera_ = false;
  SceneDescription scene_;
  GltfMaterials materials_;  // adds the materials and textures to scene_
  GltfMeshes meshes_;        // adds the meshes to scene_
  std::map<std::pair<std::uint32_t, std::array<float, 9>>, std::uint32_t> master_of_;
  std::vector<SceneNode> mesh_nodes_;
  renderer::Camera camera_;
  glm::dvec3 lo_{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi_{-std::numeric_limits<double>::infinity()};
};

// validate_description's message names the node levrt built ("/root/children/3/child/range: must
// be > 0 (0)"), a path not in the file; a child of the root is a light or mesh placed for a glTF
// node, and the camera the file's camera node, which are named instead ("nodes[7] light, as
// placed in the world: range: ...").
std::string gltf_scene_problem(const std::string& message, const std::vector<std::string>& places,
                               const std::string& camera_place) {
  if (message.rfind("/camera/", 0) == 0 && !camera_place.empty())
    return camera_place + ", as placed in the world: " + message.substr(8);
  const std::string prefix = "/root/children/";
  const std::size_t digits = message.find_first_not_of("0123456789", prefix.size());
  if (message.rfind(prefix, 0) != 0 || digits == prefix.size() || digits == std::string::npos)
    return "scene: " + message;
  const std::size_t child = std::stoul(message.substr(prefix.size(), digits - prefix.size()));
  if (child >= places.size()) return "scene: " + message;
  std::string field = message.substr(digits);  // "/child/range: must be > 0 (0)"
  if (field.rfind("/child", 0) == 0) field.erase(0, 6);
  if (field.rfind('/', 0) == 0) field.erase(0, 1);
  return places[child] + ", as placed in the world: " + field;
}

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
    throw std::invalid_argument(
        path + ": " +
        gltf_scene_problem(e.what(), importer.root_child_places(), importer.camera_place()));
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
    std::fprintf(stderr, "%s\n", escape_control_characters(path + ": warning: " + warning).c_str());
  }
  return scene;
}

}  // namespace scenes