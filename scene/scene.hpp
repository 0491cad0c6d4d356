// A scene in world space, ready for upload: triangles with per-vertex normals, materials,
// punctual lights and a default camera. Units are metres and the radiometric units of
// DESIGN.md section 2. Geometry is pre-transformed to world space (no node hierarchy here).
#pragma once

#include "api/render_request.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace scene {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};
static_assert(sizeof(Vertex) == 32, "Vertex is uploaded as-is");

// An albedo texture as stored in the file: 8-bit sRGB-encoded RGBA, decoded to linear by
// the sampler. Mip levels are made at upload.
struct Texture {
  enum class Wrap { repeat, clamp_to_edge, mirrored_repeat };
  enum class Filter { nearest, linear };
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, rows top to bottom
  Wrap wrap_u = Wrap::repeat;
  Wrap wrap_v = Wrap::repeat;
  Filter mag_filter = Filter::linear;
  Filter min_filter = Filter::linear;
  bool mipmaps = true;            // minification reads the mip chain
  Filter mip_filter = Filter::linear;
};

struct Material {
  std::string name;
  glm::vec3 base_color{0.8f};  // linear albedo (Lambertian reflectance), each channel in [0, 1]
  glm::vec3 emissive{0.0f};    // emitted radiance, W/(m^2 sr)
  // Index into Scene::textures, or -1. The albedo is base_color times the texture's
  // linear RGB at the vertex uv (which the loader takes from the texture's texcoord set).
  std::int32_t base_color_texture = -1;
  bool double_sided = false;  // emissive surfaces emit from both sides
};

// A run of triangles sharing one material.
struct Draw {
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  std::uint32_t material = 0;
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  glm::vec3 center() const { return 0.5f * (min + max); }
  float radius() const { return 0.5f * glm::length(max - min); }  // of the bounding sphere
};

struct Scene {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Draw> draws;
  std::vector<api::Light> lights;
  api::Camera camera;  // the default camera
  Bounds bounds;       // of the geometry; recompute with update_bounds() after edits
  std::vector<Bounds> draw_bounds;  // per draw, made by update_bounds() too
  std::vector<bool> draw_planar;    // per draw: all its triangles in one plane (cannot shadow itself)
  // Per planar draw, that plane: unit normal (its first triangle's winding) and offset, n.p = w;
  // zero for a draw without a triangle with an area, or one that is not planar.
  std::vector<glm::vec4> draw_plane;
  // What the loader ignored (unsupported optional features); every render's stats repeat them.
  std::vector<std::string> warnings;

  void update_bounds();
  std::size_t triangle_count() const { return indices.size() / 3; }
  // Host memory the scene holds: vertices, indices and texels.
  std::size_t memory_bytes() const;
};

}  // namespace scene
