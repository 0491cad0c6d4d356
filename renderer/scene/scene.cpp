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

}  // namespace scene
