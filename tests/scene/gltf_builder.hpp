// Writes small glTF 2.0 files for tests: meshes, materials, PNG textures, nodes, lights and
// cameras, with the binary data embedded as a base64 data: URI (or as a .glb).
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace test_gltf {

class GltfBuilder {
 public:
  GltfBuilder();

  // A solid-colour PNG texture (sRGB bytes) with an optional sampler; returns the texture index.
  int add_texture(glm::u8vec4 texel, int width = 2, int height = 2, nlohmann::json sampler = nullptr);
  // A material from its glTF JSON (e.g. {"pbrMetallicRoughness": {...}}).
  int add_material(nlohmann::json material);
  // A material whose albedo is the texture alone.
  int add_textured_material(int texture);
  // A triangle mesh; normals and uvs may be empty (then left out).
  int add_mesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
               const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices, int material = -1);
  // An axis-aligned rectangle in the plane through `center` with normal `normal` (one of
  // the axes), of the given side, facing the normal; with uvs 0..1.
  int add_quad(glm::vec3 center, glm::vec3 normal, float side, int material = -1);
  int add_light(nlohmann::json light);  // KHR_lights_punctual
  int add_camera(nlohmann::json camera);
  // A node from its JSON ("mesh", "children", "translation", ...); scene roots are listed.
  int add_node(nlohmann::json node, bool root = true);

  nlohmann::json& json() { return doc_; }
  std::string gltf() const;          // .gltf text with the buffer as a data: URI
  std::vector<std::uint8_t> glb() const;

 private:
  int add_view(const void* data, std::size_t bytes, int target);
  int add_accessor(const std::vector<float>& values, int components, const char* type, int target, bool bounds);

  nlohmann::json doc_;
  std::vector<std::uint8_t> bin_;
};

}  // namespace test_gltf
