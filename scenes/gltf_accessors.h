// glTF's binary data read for the importer (gltf_scene.h): every buffer view and accessor, sparse
// ones included, checked to lie inside its buffer before anything is read (so a truncated .bin
// is refused by name), then an accessor's elements decoded as the spec says: the view's stride,
// normalized integers, the sparse substitutions.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace scenes {

class GltfAccessors {
 public:
  // `path` names the file in refusals.
  GltfAccessors(const tinygltf::Model& model, const std::string& path)
      : model_(model), path_(path) {}

  // Every view and accessor lies inside its data; else a refusal naming it.
  void check_buffers() const;

  // Every element's components of accessor `index`, row after row; `types` lists the accessor
  // types the caller takes, `where` is the glTF path that uses it. Only after check_buffers.
  std::vector<double> read(int index, std::initializer_list<int> types,
                           const std::string& where) const;

 private:
  void check_span(const std::string& where, double byte_offset, std::size_t stride,
                  std::size_t count, std::size_t element_bytes, std::size_t view_bytes) const;
  const tinygltf::BufferView& view_at(int index, const std::string& where) const;
  void check_sparse(const tinygltf::Accessor& accessor, const std::string& where,
                    std::size_t element_bytes) const;
  const unsigned char* view_bytes(const tinygltf::BufferView& view) const;

  const tinygltf::Model& model_;
  const std::string& path_;
};

}  // namespace scenes
