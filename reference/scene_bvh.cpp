#include "reference/scene_bvh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/elapsed.hpp"
#include "reference/embree_scene.hpp"
#include "reference/texture_lookup.hpp"

namespace reference {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Relative size of the offset that lifts ray origins off their surface: about 170 ulps of the
// largest coordinate, far above Embree's intersection error and far below any feature a
// pixel resolves.
constexpr float kRelativeRayOffset = 1e-5f;

}  // namespace

SceneBvh::SceneBvh(const scene::Scene& scene) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<glm::vec3> positions;
  positions.reserve(scene.vertices.size());
  for (const scene::Vertex& v : scene.vertices) positions.push_back(v.position);

  std::vector<glm::uvec3> corners;
  std::vector<std::uint8_t> cullable;
  float extent = 0.0f;
  for (std::size_t d = 0; d < scene.draws.size(); ++d) {
    const scene::Draw& draw = scene.draws[d];
    const std::string name = "scene draw " + std::to_string(d);
    if (draw.material >= scene.materials.size())
      throw std::invalid_argument(name + " uses material " + std::to_string(draw.material) + ", but the scene has " +
                                  std::to_string(scene.materials.size()));
    if (std::uint64_t(draw.first_index) + draw.index_count > scene.indices.size())
      throw std::invalid_argument(name + " reads indices past the end of the index buffer");
    const bool single_sided = !scene.materials[draw.material].double_sided;
    for (std::uint32_t i = draw.first_index; i + 3 <= draw.first_index + draw.index_count; i += 3) {
      const glm::uvec3 t(scene.indices[i], scene.indices[i + 1], scene.indices[i + 2]);
      if (t.x >= positions.size() || t.y >= positions.size() || t.z >= positions.size())
        throw std::invalid_argument(name + " has a vertex index past the end of the vertex buffer");
      const glm::vec3 a = positions[t.x], b = positions[t.y], c = positions[t.z];
      // The rasteriser draws nothing for these; Embree would reject them or worse.
      if (!finite(a) || !finite(b) || !finite(c) || glm::cross(b - a, c - a) == glm::vec3(0.0f)) continue;
      corners.push_back(t);
      cullable.push_back(single_sided ? 1 : 0);
      triangles_.push_back({i, draw.material});
      for (glm::vec3 p : {a, b, c}) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
  }
  ray_offset_ = kRelativeRayOffset * std::max(extent, 1e-3f);
  embree_ = std::make_unique<EmbreeScene>(positions, corners, cullable);
  build_ms_ = core::ms_since(start);
}

SceneBvh::~SceneBvh() = default;

std::optional<SurfaceHit> SceneBvh::intersect(glm::vec3 origin, glm::vec3 direction, float t_far, bool camera) const {
  const auto hit = embree_->closest(origin, direction, t_far, camera);
  if (!hit) return std::nullopt;
  const Triangle& triangle = triangles_[hit->triangle];
  const scene::Vertex& v0 = scene_.vertices[scene_.indices[triangle.first_index]];
  const scene::Vertex& v1 = scene_.vertices[scene_.indices[triangle.first_index + 1]];
  const scene::Vertex& v2 = scene_.vertices[scene_.indices[triangle.first_index + 2]];
  const float w0 = 1.0f - hit->u - hit->v, w1 = hit->u, w2 = hit->v;

  SurfaceHit s;
  s.distance = hit->t;
  s.material = triangle.material;
  s.position = w0 * v0.position + w1 * v1.position + w2 * v2.position;
  s.geometric_normal = glm::normalize(glm::cross(v1.position - v0.position, v2.position - v0.position));
  const glm::vec3 interpolated = w0 * v0.normal + w1 * v1.normal + w2 * v2.normal;
  const float length = glm::length(interpolated);
  // A vertex normal that cancels out or is broken leaves the flat face's normal.
  s.shading_normal = length > 0.0f && std::isfinite(length) ? interpolated / length : s.geometric_normal;
  const bool back_face = glm::dot(s.geometric_normal, direction) > 0.0f;
  if (back_face) {
    s.geometric_normal = -s.geometric_normal;
    s.shading_normal = -s.shading_normal;
  }

  const scene::Material& material = scene_.materials[triangle.material];
  s.albedo = material.base_color;
  if (material.base_color_texture >= 0 && std::size_t(material.base_color_texture) < scene_.textures.size())
    s.albedo *= sample_texture(scene_.textures[material.base_color_texture], w0 * v0.uv + w1 * v1.uv + w2 * v2.uv);
  if (!back_face || material.double_sided) s.emitted = material.emissive;
  return s;
}

bool SceneBvh::occluded(glm::vec3 origin, glm::vec3 direction, float t_far) const {
  return embree_->occluded(origin, direction, t_far);
}

glm::vec3 SceneBvh::spawn_origin(const SurfaceHit& hit, glm::vec3 direction) const {
  const float side = glm::dot(hit.geometric_normal, direction) >= 0.0f ? 1.0f : -1.0f;
  return hit.position + side * ray_offset_ * hit.geometric_normal;
}

}  // namespace reference
