// The state shared by the parts of the glTF conversion (loader, materials, meshes): the
// parsed model, the scene being built and what has already been converted.
#pragma once

#include "scene/gltf_loader.hpp"
#include "scene/tinygltf_config.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>

namespace scene::gltf {

[[noreturn]] inline void fail(LoadError::Kind kind, const std::string& message) { throw LoadError(kind, message); }
[[noreturn]] inline void invalid(const std::string& message) { fail(LoadError::Kind::invalid, message); }

template <glm::length_t N, typename T, glm::qualifier Q>
bool all_finite(const glm::vec<N, T, Q>& v) {
  for (glm::length_t i = 0; i < N; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

struct Conversion {
  const tinygltf::Model& model;
  const LoadLimits& limits;
  Scene& scene;
  std::map<int, std::uint32_t> materials;    // glTF material (-1: the default) -> scene material
  std::map<int, std::int32_t> textures;      // glTF texture -> scene texture (-1: unusable)
  std::set<std::string> warned;              // each warning once

  void warn(const std::string& message) {
    if (warned.insert(message).second) scene.warnings.push_back(message);
  }
};

// The scene material for a primitive's glTF material index (-1: the spec's default material).
std::uint32_t material_for(Conversion& c, int gltf_material);

// The TEXCOORD set the material's base colour texture reads, or -1 for none.
int texcoord_set_of(const Conversion& c, int gltf_material);

// Appends a primitive placed by `world` (node to world) to the scene: vertices in world
// space, triangles (strips and fans unrolled) counter-clockwise from the front.
void add_primitive(Conversion& c, int mesh, int primitive, const glm::dmat4& world);

}  // namespace scene::gltf
