// Reading glTF accessors from untrusted files: every component type and normalisation the
// spec allows, byte strides, accessors without a buffer view (zeros) and sparse accessors,
// with every offset and count checked against the buffers before anything is read.
#pragma once

#include "scene/tinygltf_config.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace scene::gltf {

// Accessor `index` as `components` floats per element (its type must have that many:
// 1 SCALAR, 2 VEC2, 3 VEC3, 4 VEC4). Integer components become floats, mapped to [0, 1] or
// [-1, 1] when the accessor is normalized. `what` names the data in errors. Throws
// LoadError(invalid) for anything out of range or inconsistent.
std::vector<float> read_floats(const tinygltf::Model& model, int index, int components, const std::string& what);

// An index accessor (SCALAR of unsigned byte, short or int).
std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, int index, const std::string& what);

// The accessor's element count, checked that the accessor exists.
std::size_t element_count(const tinygltf::Model& model, int index, const std::string& what);

}  // namespace scene::gltf
