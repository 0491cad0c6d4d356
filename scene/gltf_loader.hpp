// glTF 2.0 (.gltf and .glb) into a scene::Scene: the node hierarchy flattened to world
// space, triangle primitives, base colour and emission, KHR_lights_punctual lights and the
// first perspective camera. Files are untrusted: every index, offset and count is checked,
// and what cannot be loaded raises a LoadError naming the problem; nothing crashes.
#pragma once

#include "scene/decode_budget.hpp"
#include "scene/scene.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

namespace scene {

class LoadError : public std::runtime_error {
 public:
  enum class Kind {
    invalid,      // not valid glTF: bad JSON, wrong types, indices out of range, missing data
    unsupported,  // valid, but uses what the renderer does not do (a required extension, points)
    too_complex,  // over a LoadLimits bound
    busy,         // its images could not be decoded now: other loads hold the decode budget
  };
  LoadError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

// Bounds on what one scene may hold, so a small file cannot ask for unbounded memory.
struct LoadLimits {
  std::size_t max_triangles = 8'000'000;
  std::size_t max_vertices = 16'000'000;
  std::size_t max_texels = 64u << 20;   // over all textures (4 bytes each)
  std::uint32_t max_texture_side = 16384;  // what desktop Vulkan devices sample
  std::size_t max_node_instances = 1'000'000;  // meshes placed by the node hierarchy
  // Textures larger than this per side are halved at load until they fit: a scene's
  // resident size is bounded whatever its files hold (4 MiB texels a texture at 2048).
  std::uint32_t max_kept_texture_side = 2048;
  // Shared by the loads of a process (a server's uploads and workers); null: unbounded.
  std::shared_ptr<DecodeBudget> decode_budget;
  std::chrono::milliseconds decode_wait{2000};  // for room in it, before Kind::busy
};

struct LoadOptions {
  std::string name;  // the scene's name
  // External buffers and images (uri "x.bin") are read from this directory, and only from
  // it; empty: only embedded data (data: URIs, the GLB binary chunk) is allowed, as for
  // uploaded scenes, so nothing in a file can make the loader open a path.
  std::filesystem::path external_files_dir;
  LoadLimits limits;
};

// Loads a .glb (recognised by its magic) or a .gltf from memory.
Scene load_gltf(std::span<const std::uint8_t> bytes, const LoadOptions& options);

// Loads a file from disk; external files next to it are allowed. The name is the file's stem.
Scene load_gltf_file(const std::filesystem::path& path, const LoadLimits& limits = {});

}  // namespace scene
