#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace scene {

namespace {

// The plane of the draw's first triangle with an area (unit normal, offset: n.p = w) when
// every vertex of the draw lies within a millionth of its extent of it, zero when no
// triangle has an area; nothing when the draw is not planar.
std::optional<glm::vec4> plane_of(const Scene& s, const Draw& d, const Bounds& b) {
  const float tolerance = 1e-6f * glm::length(b.max - b.min);
  glm::vec3 origin(0.0f), normal(0.0f);
  const std::uint32_t end = std::min<std::uint32_t>(d.first_index + d.index_count, std::uint32_t(s.indices.size()));
  for (std::uint32_t i = d.first_index; i + 2 < end && normal == glm::vec3(0.0f); i += 3) {
    if (s.indices[i] >= s.vertices.size() || s.indices[i + 1] >= s.vertices.size() || s.indices[i + 2] >= s.vertices.size())
      continue;
    const glm::vec3 a = s.vertices[s.indices[i]].position;
    const glm::vec3 n = glm::cross(s.vertices[s.indices[i + 1]].position - a, s.vertices[s.indices[i + 2]].position - a);
    if (glm::length(n) > 0.0f) origin = a, normal = glm::normalize(n);
  }
  for (std::uint32_t i = d.first_index; i < end; ++i)
    if (s.indices[i] < s.vertices.size() && std::abs(glm::dot(s.vertices[s.indices[i]].position - origin, normal)) > tolerance)
      return std::nullopt;
  return glm::vec4(normal, glm::dot(normal, origin));
}

}  // namespace

void Scene::update_bounds() {
  draw_bounds.clear();
  draw_planar.clear();
  draw_plane.clear();
  for (const Draw& d : draws) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (std::uint32_t i = d.first_index; i < d.first_index + d.index_count && i < indices.size(); ++i) {
      if (indices[i] >= vertices.size()) continue;
      lo = glm::min(lo, vertices[indices[i]].position);
      hi = glm::max(hi, vertices[indices[i]].position);
    }
    draw_bounds.push_back(lo.x <= hi.x ? Bounds{lo, hi} : Bounds{});
    const std::optional<glm::vec4> plane = plane_of(*this, d, draw_bounds.back());
    draw_planar.push_back(plane.has_value());
    draw_plane.push_back(plane.value_or(glm::vec4(0.0f)));
  }
  if (vertices.empty()) {
    bounds = {};
    return;
  }
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const Vertex& v : vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  bounds = {lo, hi};
}

std::size_t Scene::memory_bytes() const {
  std::size_t bytes = vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t) +
                      materials.size() * sizeof(Material) + draws.size() * sizeof(Draw);
  for (const Texture& t : textures) bytes += t.rgba.size();
  return bytes;
}

}  // namespace scene
