#include "scenes/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "scenes/gltf_refusal.h"
#include "scenes/gltf_scene.h"

namespace scenes {
namespace {

template <typename T>
T load(const unsigned char* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

// One component as stored, integers exactly (a double holds every u32).
double raw_component(const unsigned char* at, int component_type) {
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
double normalized_component(double raw, int component_type) {
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

}  // namespace

// Every view and accessor lies inside its data, so a truncated .bin fails here, by name.
void GltfAccessors::check_buffers() const {
  for (std::size_t i = 0; i < model_.bufferViews.size(); ++i) {
    const tinygltf::BufferView& view = model_.bufferViews[i];
    const std::string where = "bufferViews[" + std::to_string(i) + "]";
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
      fail_gltf(path_, where + ".buffer", std::to_string(view.buffer));
    }
    const std::size_t available = model_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteOffset > available || view.byteLength > available - view.byteOffset) {
      fail_gltf(path_, where,
                "bytes " + std::to_string(view.byteOffset) + "+" + std::to_string(view.byteLength) +
                    " beyond the buffer's " + std::to_string(available));
    }
  }
  for (std::size_t i = 0; i < model_.accessors.size(); ++i) {
    const tinygltf::Accessor& accessor = model_.accessors[i];
    const std::string where = "accessors[" + std::to_string(i) + "]";
    if (accessor.count > kMaxGltfAccessorElements)
      fail_gltf(path_, where + ".count", std::to_string(accessor.count));
    const int component_bytes =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    const int components =
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    if (component_bytes <= 0 || components <= 0)
      fail_gltf(path_, where, "unknown component type or type");
    const auto element_bytes =
        static_cast<std::size_t>(component_bytes) * static_cast<std::size_t>(components);
    if (accessor.sparse.isSparse) check_sparse(accessor, where, element_bytes);
    if (accessor.bufferView < 0) continue;  // all zeros (or sparse only): no bytes to check
    if (static_cast<std::size_t>(accessor.bufferView) >= model_.bufferViews.size()) {
      fail_gltf(path_, where + ".bufferView", std::to_string(accessor.bufferView));
    }
    const tinygltf::BufferView& view =
        model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.byteStride != 0 && view.byteStride < element_bytes) {
      fail_gltf(path_, where,
                "byteStride " + std::to_string(view.byteStride) + " below the element's " +
                    std::to_string(element_bytes) + " bytes");
    }
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
    check_span(where, accessor.byteOffset, stride, accessor.count, element_bytes, view.byteLength);
  }
}

// byte_offset + stride * (count - 1) + element_bytes within view_bytes (none when count is 0).
void GltfAccessors::check_span(const std::string& where, double byte_offset, std::size_t stride,
                               std::size_t count, std::size_t element_bytes,
                               std::size_t view_bytes) const {
  if (count == 0) return;
  const double end_bytes = byte_offset +
                           static_cast<double>(stride) * static_cast<double>(count - 1) +
                           static_cast<double>(element_bytes);
  if (byte_offset < 0.0 || end_bytes > static_cast<double>(view_bytes)) {
    fail_gltf(path_, where,
              std::to_string(count) + " elements beyond the view's " + std::to_string(view_bytes) +
                  " bytes");
  }
}

const tinygltf::BufferView& GltfAccessors::view_at(int index, const std::string& where) const {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.bufferViews.size())
    fail_gltf(path_, where + ".bufferView", std::to_string(index));
  return model_.bufferViews[static_cast<std::size_t>(index)];
}

void GltfAccessors::check_sparse(const tinygltf::Accessor& accessor, const std::string& where,
                                 std::size_t element_bytes) const {
  const int count = accessor.sparse.count;
  if (count <= 0 || static_cast<std::size_t>(count) > accessor.count)
    fail_gltf(path_, where + ".sparse.count",
              std::to_string(count) + " (from 1 to the accessor's count, " +
                  std::to_string(accessor.count) + ", is expected)");
  const int index_bytes = tinygltf::GetComponentSizeInBytes(
      static_cast<std::uint32_t>(accessor.sparse.indices.componentType));
  const int index_type = accessor.sparse.indices.componentType;
  if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail_gltf(path_, where + ".sparse.indices.componentType",
              std::to_string(index_type) + " (one of 5121 5123 5125 is expected)");
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

const unsigned char* GltfAccessors::view_bytes(const tinygltf::BufferView& view) const {
  return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
}

// Every element's components, row after row: the view's stride applied, normalized integers
// decoded, then the sparse substitutions. `types` lists the accessor types the caller takes.
std::vector<double> GltfAccessors::read(int index, std::initializer_list<int> types,
                                        const std::string& where) const {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
    fail_gltf(path_, where, "accessor " + std::to_string(index));
  const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
  const std::string accessor_where = "accessors[" + std::to_string(index) + "]";
  if (std::find(types.begin(), types.end(), accessor.type) == types.end())
    fail_gltf(path_, accessor_where + ".type",
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
      const double target = raw_component(indices + k * index_bytes, sparse.indices.componentType);
      if (target >= static_cast<double>(accessor.count))
        fail_gltf(path_, accessor_where + ".sparse.indices",
                  gltf_number_text(target) + " beyond the count " + std::to_string(accessor.count));
      const auto e = static_cast<std::size_t>(target);
      for (std::size_t c = 0; c < components; ++c) {
        values[e * components + c] = decode(replacements + (k * components + c) * component_bytes);
      }
    }
  }
  return values;
}

}  // namespace scenes
