#include "scene/gltf_accessors.hpp"

#include "api/counted.hpp"
#include "scene/gltf_convert.hpp"
#include "scene/gltf_loader.hpp"

#include <algorithm>
#include <cstring>

namespace scene::gltf {
namespace {

std::size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int components_of(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;  // matrices are not vertex data
  }
}

template <typename T>
T load(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));  // glTF data need not be aligned
  return v;
}

// One component as a float, normalised as the spec says for normalized integer accessors.
float component(const std::uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = load<std::int8_t>(p);
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const float v = load<std::uint8_t>(p);
      return normalized ? v / 255.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float v = load<std::int16_t>(p);
      return normalized ? std::max(v / 32767.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float v = load<std::uint16_t>(p);
      return normalized ? v / 65535.0f : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(load<std::uint32_t>(p));
    default: return load<float>(p);
  }
}

// An unsigned integer component (indices), exactly: a float holds only 24 bits.
std::uint32_t unsigned_component(const std::uint8_t* p, int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
    default: return load<std::uint32_t>(p);
  }
}

// `count` elements of `element_size` bytes, `stride` apart, starting `offset` bytes into
// buffer view `view`: checked to lie inside the view and the view inside its buffer.
const std::uint8_t* checked_span(const tinygltf::Model& model, int view, std::size_t offset, std::size_t count,
                                 std::size_t element_size, std::size_t stride, const std::string& what) {
  if (view < 0 || std::size_t(view) >= model.bufferViews.size())
    invalid(what + ": buffer view " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& bv = model.bufferViews[std::size_t(view)];
  if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size())
    invalid(what + ": buffer " + std::to_string(bv.buffer) + " does not exist");
  const std::vector<unsigned char>& data = model.buffers[std::size_t(bv.buffer)].data;
  if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
    invalid(what + ": buffer view " + std::to_string(view) + " reaches past the end of its buffer (" +
            api::counted(data.size(), "byte") + ")");
  if (count == 0) return data.data();
  // offset + stride * (count - 1) + element_size <= byteLength, without overflow.
  const std::size_t length = bv.byteLength;
  if (offset > length || element_size > length - offset ||
      (count - 1) > (length - offset - element_size) / std::max<std::size_t>(stride, 1))
    invalid(what + ": buffer view " + std::to_string(view) + " (" + api::counted(length, "byte") + ") is too short for " +
            api::counted(count, "element"));
  return data.data() + bv.byteOffset + offset;
}

const tinygltf::Accessor& accessor_at(const tinygltf::Model& model, int index, const std::string& what) {
  if (index < 0 || std::size_t(index) >= model.accessors.size())
    invalid(what + ": accessor " + std::to_string(index) + " does not exist");
  return model.accessors[std::size_t(index)];
}

// Where an accessor's bytes are, every bound checked: nothing is read or allocated before.
struct Layout {
  std::size_t count = 0;
  int component_type = 0;
  std::size_t component_size = 0;
  std::size_t element_size = 0;
  const std::uint8_t* dense = nullptr;  // nullptr: no buffer view, the elements are zeros
  std::size_t stride = 0;
  std::size_t sparse_count = 0;
  int sparse_index_type = 0;
  const std::uint8_t* sparse_indices = nullptr;
  const std::uint8_t* sparse_values = nullptr;
};

Layout layout_of(const tinygltf::Model& model, int index, int components, const std::string& what) {
  const tinygltf::Accessor& a = accessor_at(model, index, what);
  Layout l;
  l.count = a.count;
  l.component_type = a.componentType;
  l.component_size = component_size(a.componentType);
  if (l.component_size == 0) invalid(what + ": accessor " + std::to_string(index) + " has an invalid component type");
  if (components_of(a.type) != components)
    invalid(what + ": accessor " + std::to_string(index) + " has " + std::to_string(components_of(a.type)) +
            " components per element, expected " + std::to_string(components));
  l.element_size = l.component_size * std::size_t(components);
  if (a.bufferView >= 0) {
    const std::size_t declared =
        std::size_t(a.bufferView) < model.bufferViews.size() ? model.bufferViews[std::size_t(a.bufferView)].byteStride : 0;
    l.stride = declared == 0 ? l.element_size : declared;
    if (l.stride < l.element_size) invalid(what + ": byte stride " + std::to_string(l.stride) + " is shorter than an element");
    l.dense = checked_span(model, a.bufferView, a.byteOffset, a.count, l.element_size, l.stride, what);
  }
  if (a.sparse.isSparse) {
    if (a.sparse.count < 0 || std::size_t(a.sparse.count) > a.count)
      invalid(what + ": sparse count " + std::to_string(a.sparse.count) + " is out of range");
    l.sparse_count = std::size_t(a.sparse.count);
    l.sparse_index_type = a.sparse.indices.componentType;
    const std::size_t isize = component_size(l.sparse_index_type);
    if (l.sparse_index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        l.sparse_index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        l.sparse_index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      invalid(what + ": sparse indices must be unsigned integers");
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0) invalid(what + ": negative sparse offset");
    l.sparse_indices = checked_span(model, a.sparse.indices.bufferView, std::size_t(a.sparse.indices.byteOffset),
                                    l.sparse_count, isize, isize, what);
    l.sparse_values = checked_span(model, a.sparse.values.bufferView, std::size_t(a.sparse.values.byteOffset),
                                   l.sparse_count, l.element_size, l.element_size, what);
  }
  return l;
}

// Calls put(element, component, bytes) for the dense data, then for the sparse
// substitutions; elements without a buffer view are left as the caller zeroed them.
template <typename Put>
void read_layout(const Layout& l, int components, const std::string& what, Put put) {
  if (l.dense)
    for (std::size_t i = 0; i < l.count; ++i)
      for (int c = 0; c < components; ++c) put(i, c, l.dense + i * l.stride + std::size_t(c) * l.component_size);
  const std::size_t isize = component_size(l.sparse_index_type);
  for (std::size_t k = 0; k < l.sparse_count; ++k) {
    const std::size_t i = unsigned_component(l.sparse_indices + k * isize, l.sparse_index_type);
    if (i >= l.count) invalid(what + ": sparse index " + std::to_string(i) + " is out of range");
    for (int c = 0; c < components; ++c)
      put(i, c, l.sparse_values + k * l.element_size + std::size_t(c) * l.component_size);
  }
}

}  // namespace

std::size_t element_count(const tinygltf::Model& model, int index, const std::string& what) {
  return accessor_at(model, index, what).count;
}

std::vector<float> read_floats(const tinygltf::Model& model, int index, int components, const std::string& what) {
  const Layout l = layout_of(model, index, components, what);
  if (l.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) invalid(what + ": vertex data cannot be unsigned int");
  const bool normalized = model.accessors[std::size_t(index)].normalized;
  std::vector<float> out(l.count * std::size_t(components), 0.0f);
  read_layout(l, components, what, [&](std::size_t i, int c, const std::uint8_t* p) {
    out[i * std::size_t(components) + std::size_t(c)] = component(p, l.component_type, normalized);
  });
  return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& what) {
  const Layout l = layout_of(model, index, 1, what);
  if (l.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      l.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      l.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    invalid(what + ": indices must be unsigned byte, short or int");
  std::vector<std::uint32_t> out(l.count, 0u);
  read_layout(l, 1, what, [&](std::size_t i, int, const std::uint8_t* p) {
    out[i] = unsigned_component(p, l.component_type);
  });
  return out;
}

}  // namespace scene::gltf
