#include "renderer/scene/scene.hpp"

#include <limits>

namespace scene {

void Scene::update_bounds() {
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
