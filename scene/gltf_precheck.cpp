#include "scene/gltf_precheck.hpp"

#include "scene/gltf_convert.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <set>
#include <string_view>

namespace scene::gltf {
namespace {

const std::set<std::string> kSupportedExtensions = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                    "KHR_mesh_quantization"};

std::uint32_t u32le(std::span<const std::uint8_t> bytes, std::size_t at) {
  return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 | std::uint32_t(bytes[at + 2]) << 16 |
         std::uint32_t(bytes[at + 3]) << 24;
}

// `what`: the version a file names, 'glTF version "3.0"'.
[[noreturn]] void version_unsupported(const std::string& what) {
  fail(LoadError::Kind::unsupported, what + " is not supported (2.0 only)");
}
// `why`: what shows the file is glTF 1.0.
[[noreturn]] void gltf_1_unsupported(const std::string& why) {
  fail(LoadError::Kind::unsupported, "glTF 1.0 is not supported (2.0 only): " + why);
}

// The JSON text: the whole file, or a .glb's first chunk (empty when the header says
// otherwise: tinygltf reports that). A .glb's own version comes first.
std::string_view json_text(std::span<const std::uint8_t> bytes) {
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary) return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
  if (bytes.size() < 20) return {};
  const std::uint32_t version = u32le(bytes, 4);
  if (version == 1) gltf_1_unsupported("a binary glTF 1.0 file (KHR_binary_glTF)");
  if (version != 2) version_unsupported("binary glTF version " + std::to_string(version));
  const std::uint32_t length = u32le(bytes, 12);
  constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
  if (u32le(bytes, 16) != kJsonChunk || length > bytes.size() - 20) return {};
  return {reinterpret_cast<const char*>(bytes.data()) + 20, length};
}

void check_version(const nlohmann::json& doc) {
  const auto asset = doc.find("asset");
  if (asset == doc.end()) gltf_1_unsupported("the file has no \"asset\", which glTF 2.0 requires");
  if (!asset->is_object() || !asset->contains("version")) return;  // invalid in any version: tinygltf says so
  const auto version = asset->find("version");
  // "2.0" (or "2.1": minor versions stay compatible); glTF 1.0 files also wrote a number.
  const std::string text = version->is_string() ? version->get<std::string>() : version->dump();
  if (text == "2" || text.starts_with("2.")) return;
  if (text == "1" || text.starts_with("1.")) gltf_1_unsupported("asset.version is " + version->dump());
  version_unsupported("glTF version " + version->dump());
}

void check_required_extensions(const nlohmann::json& doc) {
  const auto required = doc.find("extensionsRequired");
  if (required == doc.end() || !required->is_array()) return;
  for (const nlohmann::json& name : *required) {
    if (!name.is_string()) continue;
    const std::string ext = name.get<std::string>();
    if (supported_extension(ext)) continue;
    const bool compressed = ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression";
    fail(LoadError::Kind::unsupported, "required extension " + ext + " is not supported" +
                                           (compressed ? " (compressed meshes: export the file uncompressed)" : ""));
  }
}

}  // namespace

bool supported_extension(const std::string& name) { return kSupportedExtensions.count(name) != 0; }

void check_declarations(std::span<const std::uint8_t> bytes) {
  const std::string_view text = json_text(bytes);
  if (text.empty()) return;
  // Only the top level and its members' members are kept (asset.version, the names in
  // extensionsRequired): a file's embedded buffers are read past, not copied. The parser is
  // iterative, so deep nesting cannot exhaust the stack.
  const auto shallow = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) { return depth <= 2; };
  const nlohmann::json doc = nlohmann::json::parse(text, shallow, /*allow_exceptions=*/false);
  if (!doc.is_object()) return;
  check_version(doc);
  check_required_extensions(doc);
}

}  // namespace scene::gltf
