#include "gltf_builder.hpp"

#include "image/png.hpp"

#include <cstring>

namespace test_gltf {
namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[n & 63] : '=';
  }
  return out;
}

void pad4(std::vector<std::uint8_t>& bytes, std::uint8_t fill) {
  while (bytes.size() % 4) bytes.push_back(fill);
}

}  // namespace

GltfBuilder::GltfBuilder() {
  doc_ = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};
}

int GltfBuilder::add_view(const void* data, std::size_t bytes, int target) {
  pad4(bin_, 0);
  const std::size_t offset = bin_.size();
  bin_.resize(offset + bytes);
  std::memcpy(bin_.data() + offset, data, bytes);
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  if (target) view["target"] = target;
  doc_["bufferViews"].push_back(view);
  return int(doc_["bufferViews"].size() - 1);
}

int GltfBuilder::add_accessor(const std::vector<float>& values, int components, const char* type, int target,
                              bool bounds) {
  const int view = add_view(values.data(), values.size() * sizeof(float), target);
  nlohmann::json a = {{"bufferView", view}, {"componentType", 5126}, {"count", values.size() / components}, {"type", type}};
  if (bounds) {
    std::vector<float> lo(components, 1e30f), hi(components, -1e30f);
    for (std::size_t i = 0; i < values.size(); ++i) {
      lo[i % components] = std::min(lo[i % components], values[i]);
      hi[i % components] = std::max(hi[i % components], values[i]);
    }
    a["min"] = lo;
    a["max"] = hi;
  }
  doc_["accessors"].push_back(a);
  return int(doc_["accessors"].size() - 1);
}

int GltfBuilder::add_texture(glm::u8vec4 texel, int width, int height, nlohmann::json sampler) {
  image::Rgba8Image img;
  img.width = std::uint32_t(width);
  img.height = std::uint32_t(height);
  for (int i = 0; i < width * height; ++i) img.pixels.insert(img.pixels.end(), {texel.r, texel.g, texel.b, texel.a});
  const std::vector<std::uint8_t> png = image::encode_png(img);
  const int view = add_view(png.data(), png.size(), 0);
  doc_["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
  nlohmann::json texture = {{"source", doc_["images"].size() - 1}};
  if (!sampler.is_null()) {
    doc_["samplers"].push_back(sampler);
    texture["sampler"] = doc_["samplers"].size() - 1;
  }
  doc_["textures"].push_back(texture);
  return int(doc_["textures"].size() - 1);
}

int GltfBuilder::add_material(nlohmann::json material) {
  doc_["materials"].push_back(std::move(material));
  return int(doc_["materials"].size() - 1);
}

int GltfBuilder::add_textured_material(int texture) {
  return add_material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}}}});
}

int GltfBuilder::add_mesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                          const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices, int material) {
  auto flat = [](const auto& vs, int n) {
    std::vector<float> out;
    for (const auto& v : vs)
      for (int i = 0; i < n; ++i) out.push_back(v[i]);
    return out;
  };
  nlohmann::json attributes = {{"POSITION", add_accessor(flat(positions, 3), 3, "VEC3", 34962, true)}};
  if (!normals.empty()) attributes["NORMAL"] = add_accessor(flat(normals, 3), 3, "VEC3", 34962, false);
  if (!uvs.empty()) attributes["TEXCOORD_0"] = add_accessor(flat(uvs, 2), 2, "VEC2", 34962, false);
  nlohmann::json primitive = {{"attributes", attributes}};
  if (!indices.empty()) {
    const int view = add_view(indices.data(), indices.size() * 4, 34963);
    doc_["accessors"].push_back({{"bufferView", view}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
    primitive["indices"] = doc_["accessors"].size() - 1;
  }
  if (material >= 0) primitive["material"] = material;
  doc_["meshes"].push_back({{"primitives", {primitive}}});
  return int(doc_["meshes"].size() - 1);
}

int GltfBuilder::add_quad(glm::vec3 center, glm::vec3 normal, float side, int material) {
  // Two tangents with t1 x t2 = normal, so the corners run counter-clockwise seen from the front.
  const glm::vec3 helper = std::abs(normal.y) > 0.5f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 t1 = glm::normalize(glm::cross(helper, normal)) * (0.5f * side);
  const glm::vec3 t2 = glm::cross(normal, t1);
  const std::vector<glm::vec3> p = {center - t1 - t2, center + t1 - t2, center + t1 + t2, center - t1 + t2};
  return add_mesh(p, std::vector<glm::vec3>(4, normal), {{0, 1}, {1, 1}, {1, 0}, {0, 0}}, {0, 1, 2, 0, 2, 3}, material);
}

int GltfBuilder::add_light(nlohmann::json light) {
  doc_["extensions"]["KHR_lights_punctual"]["lights"].push_back(std::move(light));
  if (!doc_.contains("extensionsUsed")) doc_["extensionsUsed"] = {"KHR_lights_punctual"};
  return int(doc_["extensions"]["KHR_lights_punctual"]["lights"].size() - 1);
}

int GltfBuilder::add_camera(nlohmann::json camera) {
  doc_["cameras"].push_back(std::move(camera));
  return int(doc_["cameras"].size() - 1);
}

int GltfBuilder::add_node(nlohmann::json node, bool root) {
  doc_["nodes"].push_back(std::move(node));
  const int index = int(doc_["nodes"].size() - 1);
  if (root) doc_["scenes"][0]["nodes"].push_back(index);
  return index;
}

std::string GltfBuilder::gltf() const {
  nlohmann::json doc = doc_;
  if (!bin_.empty())
    doc["buffers"] = {{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}};
  return doc.dump();
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
  nlohmann::json doc = doc_;
  doc["buffers"] = {{{"byteLength", bin_.size()}}};
  std::string text = doc.dump();
  std::vector<std::uint8_t> json(text.begin(), text.end()), bin = bin_;
  pad4(json, ' ');
  pad4(bin, 0);
  std::vector<std::uint8_t> out;
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
  };
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  u32(std::uint32_t(json.size()));
  u32(0x4E4F534A);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  u32(std::uint32_t(bin.size()));
  u32(0x004E4942);  // "BIN\0"
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

}  // namespace test_gltf
