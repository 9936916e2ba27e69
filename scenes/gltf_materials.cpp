#include "scenes/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <utility>

#include <stb/stb_image.h>

#include "scenes/gltf_refusal.h"
#include "scenes/scene_file.h"

namespace scenes {
namespace {

renderer::TextureWrap texture_wrap(int gltf_wrap) {
  switch (gltf_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return renderer::TextureWrap::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return renderer::TextureWrap::mirrored_repeat;
    default:
      return renderer::TextureWrap::repeat;
  }
}

// An image's encoded bytes: its buffer view's (bounds checked by the importer before any
// material is read), or those of the file or data URI tinygltf read.
std::pair<const unsigned char*, std::size_t> image_bytes(const tinygltf::Model& model, int index) {
  const tinygltf::Image& image = model.images[static_cast<std::size_t>(index)];
  if (image.bufferView >= 0 &&
      static_cast<std::size_t>(image.bufferView) < model.bufferViews.size()) {
    const tinygltf::BufferView& view =
        model.bufferViews[static_cast<std::size_t>(image.bufferView)];
    return {model.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset,
            view.byteLength};
  }
  return {image.image.data(), image.image.size()};
}

// The number an extension's member holds, `fallback` when it is absent (the document check has
// refused any other type already).
double extension_number(const tinygltf::Material& material, const char* extension,
                        const char* member, double fallback) {
  const auto found = material.extensions.find(extension);
  if (found == material.extensions.end()) return fallback;
  const tinygltf::Value& value = found->second.Get(member);
  return value.IsNumber() ? value.GetNumberAsDouble() : fallback;
}

}  // namespace

GltfMaterials::GltfMaterials(const tinygltf::Model& model, const std::string& path,
                             GltfBudget& budget, SceneDescription& scene)
    : model_(model), path_(path), budget_(budget), scene_(scene) {}

std::uint32_t GltfMaterials::scene_material(int index, const std::string& where) {
  if (index >= static_cast<int>(model_.materials.size()))
    fail_gltf(path_, where + ".material", std::to_string(index));
  constexpr std::uint32_t kUnread = std::numeric_limits<std::uint32_t>::max();
  const std::size_t slot = static_cast<std::size_t>(index + 1);  // 0: the default material
  if (material_of_.empty()) material_of_.assign(model_.materials.size() + 1, kUnread);
  if (material_of_[slot] != kUnread) return material_of_[slot];
  const tinygltf::Material fallback;  // the spec's default: white, metallic 1, roughness 1
  const tinygltf::Material& source =
      index >= 0 ? model_.materials[static_cast<std::size_t>(index)] : fallback;
  const std::string name =
      index >= 0 ? "gltf material " + std::to_string(index) : "gltf default material";
  material_of_[slot] =
      add_material(scene_, name,
                   read_material(source, index >= 0 ? "materials[" + std::to_string(index) + "]"
                                                    : "default material"));
  return material_of_[slot];
}

// The mapping scenes/README.md tabulates.
renderer::Material GltfMaterials::read_material(const tinygltf::Material& source,
                                                const std::string& where) {
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() != 4)
    fail_gltf(path_, where + ".baseColorFactor",
              std::to_string(pbr.baseColorFactor.size()) + " values");
  for (const double c : pbr.baseColorFactor) {
    if (!std::isfinite(c) || c < 0.0 || c > 1.0)
      fail_gltf(path_, where + ".baseColorFactor", gltf_number_text(c));
  }
  const double metallic = pbr.metallicFactor;
  const double roughness = pbr.roughnessFactor;
  if (!std::isfinite(metallic) || metallic < 0.0 || metallic > 1.0)
    fail_gltf(path_, where + ".metallicFactor", gltf_number_text(metallic));
  if (!std::isfinite(roughness) || roughness < 0.0 || roughness > 1.0)
    fail_gltf(path_, where + ".roughnessFactor", gltf_number_text(roughness));
  const double gloss = 1.0 - roughness;
  renderer::Material m;
  m.colour = glm::vec3(static_cast<float>(pbr.baseColorFactor[0]),
                       static_cast<float>(pbr.baseColorFactor[1]),
                       static_cast<float>(pbr.baseColorFactor[2]));
  if (pbr.baseColorTexture.index >= 0)
    m.colour_texture = scene_texture(pbr.baseColorTexture, where + ".baseColorTexture", false);
  m.kd = static_cast<float>(1.0 - metallic * gloss);
  m.ks = static_cast<float>(gloss * (0.04 + 0.96 * metallic));
  const double alpha = std::max(roughness * roughness, 0.01);
  m.shininess = static_cast<float>(std::clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 10000.0));
  m.kr = static_cast<float>(metallic * gloss * gloss);
  const double kt =
      extension_number(source, "KHR_materials_transmission", "transmissionFactor", 0.0);
  if (!std::isfinite(kt) || kt < 0.0 || kt > 1.0)
    fail_gltf(path_, where + ".KHR_materials_transmission.transmissionFactor",
              gltf_number_text(kt));
  m.kt = static_cast<float>(kt);
  m.kd *= static_cast<float>(1.0 - kt);
  const double ior = extension_number(source, "KHR_materials_ior", "ior", 1.5);
  if (!std::isfinite(ior) || ior < 1.0 || ior > 100.0)
    fail_gltf(path_, where + ".KHR_materials_ior.ior", gltf_number_text(ior));
  m.ior = static_cast<float>(ior);

  // Emission: factor x strength (x the texture at the hit's uv).
  if (!source.emissiveFactor.empty() && source.emissiveFactor.size() != 3)
    fail_gltf(path_, where + ".emissiveFactor",
              std::to_string(source.emissiveFactor.size()) + " values");
  const double strength =
      extension_number(source, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
  if (!std::isfinite(strength) || strength < 0.0)
    fail_gltf(path_, where + ".extensions.KHR_materials_emissive_strength.emissiveStrength",
              gltf_number_text(strength));
  for (std::size_t c = 0; c < source.emissiveFactor.size(); ++c) {
    const double e = source.emissiveFactor[c];
    if (!std::isfinite(e) || e < 0.0 || e > 1.0)
      fail_gltf(path_, where + ".emissiveFactor", gltf_number_text(e));
    m.emission[static_cast<int>(c)] = static_cast<float>(e * strength);
  }
  if (source.emissiveTexture.index >= 0 && m.has_emission())
    m.emission_texture = scene_texture(source.emissiveTexture, where + ".emissiveTexture", false);

  m.unlit = source.extensions.count("KHR_materials_unlit") != 0;
  m.cull_back_faces = !source.doubleSided;
  if (source.alphaMode == "MASK") {
    const double cutoff = source.alphaCutoff;
    if (!std::isfinite(cutoff) || cutoff < 0.0)
      fail_gltf(path_, where + ".alphaCutoff", gltf_number_text(cutoff));
    m.alpha_cutoff = static_cast<float>(cutoff);
    m.alpha_factor = static_cast<float>(pbr.baseColorFactor[3]);
    if (m.colour_texture >= 0)
      m.alpha_texture = scene_texture(pbr.baseColorTexture, where + ".baseColorTexture", true);
  } else if (source.alphaMode == "BLEND") {
    ignore("alphaMode BLEND (drawn opaque)", where);
  } else if (source.alphaMode != "OPAQUE") {
    // An unknown mode is only the validator's warning.
    ignore("alphaMode '" + escape_control_characters(source.alphaMode) + "' (drawn opaque)", where);
  }
  if (source.normalTexture.index >= 0) ignore("normalTexture", where);
  if (source.occlusionTexture.index >= 0) ignore("occlusionTexture", where);
  if (pbr.metallicRoughnessTexture.index >= 0) ignore("metallicRoughnessTexture", where);
  return m;
}

// The scene texture of a material's texture (each glTF texture decoded once; once more, keeping
// only its alpha in every channel, for a cut-out), or -1 when its texCoord is not 0.
std::int32_t GltfMaterials::scene_texture(const tinygltf::TextureInfo& info,
                                          const std::string& where, bool alpha) {
  if (info.index >= static_cast<int>(model_.textures.size()))
    fail_gltf(path_, where + ".index", std::to_string(info.index));
  if (info.texCoord != 0) {
    ignore("texCoord other than 0 (untextured)", where);
    return -1;
  }
  const auto key = std::make_pair(info.index, alpha);
  const auto found = texture_of_.find(key);
  if (found != texture_of_.end()) return found->second;
  const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(info.index)];
  const std::string texture_where = "textures[" + std::to_string(info.index) + "]";
  if (texture.source < 0 || texture.source >= static_cast<int>(model_.images.size()))
    fail_gltf(path_, texture_where + ".source", std::to_string(texture.source));
  charge_texture(info.index, alpha);
  const std::string image_where = "images[" + std::to_string(texture.source) + "]";
  const auto [bytes, size] = image_bytes(model_, texture.source);
  if (size == 0 || size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    fail_gltf(path_, image_where, "no image data (" + std::to_string(size) + " bytes)");
  const int channels_wanted = alpha ? 4 : 3;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height,
                                                &channels, channels_wanted);
  // Out of memory is no fault of the file: exit 1 as everywhere, not 2.
  if (!pixels && std::strcmp(stbi_failure_reason(), "outofmem") == 0) throw std::bad_alloc();
  if (!pixels)
    fail_gltf(path_, image_where, std::string("cannot decode: ") + stbi_failure_reason());
  renderer::Texture out;
  out.width = width;
  out.height = height;
  out.texels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < out.texels.size(); ++i) {
    const unsigned char* texel = pixels + static_cast<std::size_t>(channels_wanted) * i;
    out.texels[i] =
        alpha ? glm::vec3(texel[3] / 255.0f) : glm::vec3(texel[0], texel[1], texel[2]) / 255.0f;
  }
  stbi_image_free(pixels);
  if (texture.sampler >= 0) {
    if (texture.sampler >= static_cast<int>(model_.samplers.size()))
      fail_gltf(path_, texture_where + ".sampler", std::to_string(texture.sampler));
    const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
    out.wrap_u = texture_wrap(sampler.wrapS);
    out.wrap_v = texture_wrap(sampler.wrapT);
  }
  scene_.textures.push_back(std::move(out));
  const auto slot = static_cast<std::int32_t>(scene_.textures.size() - 1);
  texture_of_.emplace(key, slot);
  return slot;
}

void GltfMaterials::charge_material(int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.materials.size()) return;
  const tinygltf::Material& material = model_.materials[static_cast<std::size_t>(index)];
  const tinygltf::TextureInfo& base = material.pbrMetallicRoughness.baseColorTexture;
  if (base.index >= 0 && base.texCoord == 0) {
    charge_texture(base.index, false);
    if (material.alphaMode == "MASK") charge_texture(base.index, true);
  }
  const tinygltf::TextureInfo& emissive = material.emissiveTexture;
  if (emissive.index >= 0 && emissive.texCoord == 0) charge_texture(emissive.index, false);
}

// A texture's texels as decoded, from its image's header (stb reads only the header): every
// texture that samples an image decodes it anew, so each is charged (an alpha decode too).
void GltfMaterials::charge_texture(int index, bool alpha) {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.textures.size()) return;
  bool& charged = charged_[std::make_pair(index, alpha)];
  if (charged) return;
  charged = true;
  const int source = model_.textures[static_cast<std::size_t>(index)].source;
  if (source < 0 || static_cast<std::size_t>(source) >= model_.images.size()) return;
  const auto [bytes, size] = image_bytes(model_, source);
  int width = 0, height = 0, channels = 0;
  if (size == 0 || size > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      !stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels))
    return;  // refused, by name, when the texture is decoded
  const std::uint64_t texels =
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  budget_.charge(texels, kGltfBytesPerTexel,
                 "textures[" + std::to_string(index) + "] (images[" + std::to_string(source) +
                     "], " + std::to_string(width) + "x" + std::to_string(height) +
                     " texels as decoded" + (alpha ? ", its alpha for a cut-out)" : ")"));
}

void GltfMaterials::ignore(const std::string& what, const std::string& where) {
  ignored_.emplace(what, where);
}

std::vector<std::string> GltfMaterials::warnings() const {
  std::vector<std::string> lines;
  for (const auto& [what, first] : ignored_)
    lines.push_back("materials: " + what + " not rendered (the first: " + first + ")");
  return lines;
}

}  // namespace scenes
