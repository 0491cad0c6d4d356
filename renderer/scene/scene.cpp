#include "renderer/scene/scene.hpp"

#include <limits>

namespace scene {

void Scene::update_bounds() {
  draw_bounds.clear();
  for (const Draw& d : draws) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (std::uint32_t i = d.first_index; i < d.first_index + d.index_count && i < indices.size(); ++i) {
      if (indices[i] >= vertices.size()) continue;
      lo = glm::min(lo, vertices[indices[i]].position);
      hi = glm::max(hi, vertices[indices[i]].position);
    }
    draw_bounds.push_back(lo.x <= hi.x ? Bounds{lo, hi} : Bounds{});
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
