// glTF meshes read for the importer (gltf_scene.h): each triangle primitive (triangles, strips,
// fans; points and lines skipped with a warning) built into a renderer::TriangleMesh, with flat
// normals where it has none (the spec), each glTF mesh converted once into one scene mesh; and,
// before anything is built, the scene's budget charged for every mesh its nodes draw.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "renderer/geometry.h"
#include "scenes/gltf_accessors.h"
#include "scenes/gltf_budget.h"
#include "scenes/gltf_materials.h"
#include "scenes/scene_description.h"

namespace scenes {

class GltfMeshes {
 public:
  // Meshes are added to `scene`, their materials through `materials`; what is skipped is
  // appended to `warnings`; `path` names the file in refusals.
  GltfMeshes(const tinygltf::Model& model, const std::string& path, GltfBudget& budget,
             GltfMaterials& materials, SceneDescription& scene, std::vector<std::string>& warnings);

  // Every buffer view and accessor lies inside its data (GltfAccessors::check_buffers).
  void check_buffers() const;

  // Charges, before anything is built, every mesh the scene's nodes draw and every texture their
  // materials sample. Nodes are walked with a stack of their own, each at most once.
  void charge_scene(const std::vector<int>& roots);

  // scene_mesh's answer for a glTF mesh without triangles.
  static constexpr std::uint32_t kNoMesh = std::numeric_limits<std::uint32_t>::max();

  // The scene mesh of glTF mesh `index` (converted once), or kNoMesh when it has no triangles;
  // `where` is the node drawing it.
  std::uint32_t scene_mesh(int index, const std::string& where);

  // A scene mesh's bounding box in its own frame.
  const std::pair<glm::vec3, glm::vec3>& bounds(std::uint32_t scene_mesh) const {
    return mesh_bounds_[scene_mesh];
  }

  // Primitives without POSITION (not rendered, the spec) met so far, and the first one's path.
  std::size_t positionless_primitives() const { return positionless_primitives_; }
  const std::string& first_positionless() const { return first_positionless_; }

 private:
  std::uint64_t accessor_count(int index) const;
  void charge_mesh(int index);
  renderer::TriangleMesh read_primitive(const tinygltf::Primitive& primitive,
                                        const std::string& where);

  static constexpr std::uint32_t kUnconverted = kNoMesh - 1;
  const tinygltf::Model& model_;
  const std::string& path_;
  GltfBudget& budget_;
  GltfMaterials& materials_;
  SceneDescription& scene_;
  std::vector<std::string>& warnings_;
  GltfAccessors accessors_;
  std::vector<std::uint32_t> mesh_of_;  // per glTF mesh: its scene mesh
  std::vector<bool> charged_meshes_;    // per glTF mesh: charged to the budget
  std::vector<std::pair<glm::vec3, glm::vec3>> mesh_bounds_;  // per scene mesh, in its frame
  std::size_t positionless_primitives_ = 0;
  std::string first_positionless_;  // the glTF path of the first one, for the warning
};

}  // namespace scenes
