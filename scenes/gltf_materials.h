// glTF materials read into levrt's (renderer/material.h) for the importer (gltf_scene.h), each
// once, with the textures they sample (each decoded once through stb_image, its texels charged to
// the scene's budget first). pbrMetallicRoughness is mapped onto Phong as scenes/README.md
// tabulates; emissiveFactor x KHR_materials_emissive_strength x the emissive texture is the
// emission; KHR_materials_unlit shows the base colour as is; doubleSided false culls back faces
// for camera rays; alphaMode MASK cuts out where the base colour alpha (factor x texture) is
// below alphaCutoff. What a material carries that levrt does not render (BLEND drawn opaque, the
// normal, occlusion and metallic-roughness textures, texCoord other than 0) is named in warnings.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_budget.h"
#include "scenes/scene_description.h"

namespace scenes {

class GltfMaterials {
 public:
  // Materials and textures are added to `scene`; `path` names the file in refusals.
  GltfMaterials(const tinygltf::Model& model, const std::string& path, GltfBudget& budget,
                SceneDescription& scene);

  // The scene material of glTF material `index` (-1: the spec's default material); `where` is
  // the primitive using it, for a refusal of the index.
  std::uint32_t scene_material(int index, const std::string& where);

  // Charges to the budget the texels of every texture material `index` decodes (before any mesh
  // or texture is built).
  void charge_material(int index);

  // One line per kind of thing ignored, naming the first material that has it.
  std::vector<std::string> warnings() const;

 private:
  renderer::Material read_material(const tinygltf::Material& source, const std::string& where);
  std::int32_t scene_texture(const tinygltf::TextureInfo& info, const std::string& where,
                             bool alpha);
  void charge_texture(int index, bool alpha);
  void ignore(const std::string& what, const std::string& where);

  const tinygltf::Model& model_;
  const std::string& path_;
  GltfBudget& budget_;
  SceneDescription& scene_;
  std::vector<std::uint32_t> material_of_;  // [0]: the default material, [i + 1]: glTF material i
  // (glTF texture, alpha) -> its scene texture; charged: those charged to the budget.
  std::map<std::pair<int, bool>, std::int32_t> texture_of_;
  std::map<std::pair<int, bool>, bool> charged_;
  std::map<std::string, std::string> ignored_;  // what -> the first material with it
};

}  // namespace scenes
