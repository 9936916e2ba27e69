// Builds small glTF 2.0 files in tests through tinygltf's writer: raw bytes go into one buffer
// (embedded as a data URI), views and accessors describe them exactly as a test needs (strides,
// offsets, normalized integers, sparse substitutions), and text() gives the .gltf JSON.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>
#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace levrt_test {

class GltfBuilder {
 public:
  GltfBuilder() {
    model.asset.version = "2.0";
    model.buffers.emplace_back();
    model.scenes.emplace_back();
    model.defaultScene = 0;
  }

  // Appends raw values (4-byte aligned) as a new buffer view; byte_stride 0 = tightly packed.
  template <typename T>
  int add_view(const std::vector<T>& values, int byte_stride = 0) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    while (data.size() % 4 != 0) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    view.byteStride = static_cast<std::size_t>(byte_stride);
    data.resize(data.size() + view.byteLength);
    if (!values.empty()) std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
  }

  int add_accessor(int view, int component_type, int type, std::size_t count,
                   bool normalized = false, std::size_t byte_offset = 0) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = count;
    accessor.normalized = normalized;
    accessor.byteOffset = byte_offset;
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
  }

  int add_vec3s(const std::vector<glm::vec3>& values) {
    std::vector<float> flat;
    for (const glm::vec3& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
    return add_accessor(add_view(flat), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                        values.size());
  }

  // A mesh of one primitive; attributes name accessors ("POSITION", "NORMAL", "TEXCOORD_0").
  // tinygltf's writer puts `mode` in the file even when it is -1, which the spec forbids (the
  // reader refuses it), so "no mode" is written as triangles, the spec's default.
  int add_mesh(const std::map<std::string, int>& attributes, int indices = -1,
               int mode = TINYGLTF_MODE_TRIANGLES, int material = -1,
               const std::string& name = "") {
    tinygltf::Primitive primitive;
    primitive.attributes = attributes;
    primitive.indices = indices;
    primitive.mode = mode;
    primitive.material = material;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    return static_cast<int>(model.meshes.size() - 1);
  }

  // A node; a root node is listed in the scene.
  int add_node(const tinygltf::Node& node, bool root = true) {
    model.nodes.push_back(node);
    const int index = static_cast<int>(model.nodes.size() - 1);
    if (root) model.scenes[0].nodes.push_back(index);
    return index;
  }

  // A KHR_lights_punctual light, returned as its index.
  int add_light(const tinygltf::Light& light) {
    if (model.extensionsUsed.empty()) model.extensionsUsed.push_back("KHR_lights_punctual");
    model.lights.push_back(light);
    return static_cast<int>(model.lights.size() - 1);
  }

  static tinygltf::Node light_node(int light) {
    tinygltf::Node node;
    tinygltf::Value::Object index;
    index["light"] = tinygltf::Value(light);
    node.extensions["KHR_lights_punctual"] = tinygltf::Value(index);
    return node;
  }

  // A PNG image of width x height texels of `channels` 8-bit values each (RGB, or RGBA with 4),
  // row 0 first, stored in a buffer view, sampled by a new texture with the given glTF wrap
  // modes; returns the texture's index.
  int add_png_texture(int width, int height, const std::vector<std::uint8_t>& rgb, int wrap_s,
                      int wrap_t, int channels = 3) {
    std::vector<std::uint8_t> png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
          auto* out = static_cast<std::vector<std::uint8_t>*>(context);
          out->insert(out->end(), static_cast<std::uint8_t*>(data),
                      static_cast<std::uint8_t*>(data) + size);
        },
        &png, width, height, channels, rgb.data(), width * channels);
    tinygltf::Image image;
    image.bufferView = add_view(png);
    image.mimeType = "image/png";
    model.images.push_back(image);
    tinygltf::Sampler sampler;
    sampler.wrapS = wrap_s;
    sampler.wrapT = wrap_t;
    model.samplers.push_back(sampler);
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model.images.size() - 1);
    texture.sampler = static_cast<int>(model.samplers.size() - 1);
    model.textures.push_back(texture);
    return static_cast<int>(model.textures.size() - 1);
  }

  std::string text() {
    tinygltf::TinyGLTF writer;
    std::ostringstream out;
    writer.WriteGltfSceneToStream(&model, out, false, false);
    return out.str();
  }

  tinygltf::Model model;
};

}  // namespace levrt_test
