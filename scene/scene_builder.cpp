#include "scene/scene_builder.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace scene {

SceneBuilder::SceneBuilder(std::string name) { scene_.name = std::move(name); }

std::uint32_t SceneBuilder::add_material(const Material& material) {
  scene_.materials.push_back(material);
  return static_cast<std::uint32_t>(scene_.materials.size() - 1);
}

void SceneBuilder::add_quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, std::uint32_t material) {
  const glm::vec3 normal = glm::normalize(glm::cross(p1 - p0, p3 - p0));
  const auto base = static_cast<std::uint32_t>(scene_.vertices.size());
  scene_.vertices.push_back({p0, normal, {0, 0}});
  scene_.vertices.push_back({p1, normal, {1, 0}});
  scene_.vertices.push_back({p2, normal, {1, 1}});
  scene_.vertices.push_back({p3, normal, {0, 1}});

  // Consecutive quads of one material share a draw.
  const auto first = static_cast<std::uint32_t>(scene_.indices.size());
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene_.indices.push_back(base + i);
  if (!scene_.draws.empty() && scene_.draws.back().material == material &&
      scene_.draws.back().first_index + scene_.draws.back().index_count == first) {
    scene_.draws.back().index_count += 6;
  } else {
    scene_.draws.push_back({first, 6, material});
  }
}

void SceneBuilder::add_facing_quad(glm::vec3 center, glm::vec3 normal, float size, std::uint32_t material) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, n)) * (0.5f * size);
  const glm::vec3 v = glm::cross(n, u);  // |v| = |u|, u x v = n |u|^2: counter-clockwise from the front
  add_quad(center - u - v, center + u - v, center + u + v, center - u + v, material);
}

void SceneBuilder::add_box(glm::vec3 base_center, glm::vec3 size, float yaw_deg, std::uint32_t material) {
  const glm::mat4 to_world = glm::rotate(glm::translate(glm::mat4(1.0f), base_center), glm::radians(yaw_deg),
                                         glm::vec3(0, 1, 0));
  const glm::vec3 h = 0.5f * size;
  auto corner = [&](float sx, float sy, float sz) {
    return glm::vec3(to_world * glm::vec4(sx * h.x, sy > 0 ? size.y : 0.0f, sz * h.z, 1.0f));
  };
  // Corners indexed by signs; each face listed counter-clockwise seen from outside.
  add_quad(corner(-1, 1, 1), corner(1, 1, 1), corner(1, 1, -1), corner(-1, 1, -1), material);      // top
  add_quad(corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1), material);  // bottom
  add_quad(corner(-1, -1, 1), corner(1, -1, 1), corner(1, 1, 1), corner(-1, 1, 1), material);      // +z
  add_quad(corner(1, -1, -1), corner(-1, -1, -1), corner(-1, 1, -1), corner(1, 1, -1), material);  // -z
  add_quad(corner(1, -1, 1), corner(1, -1, -1), corner(1, 1, -1), corner(1, 1, 1), material);      // +x
  add_quad(corner(-1, -1, -1), corner(-1, -1, 1), corner(-1, 1, 1), corner(-1, 1, -1), material);  // -x
}

Scene SceneBuilder::build() {
  scene_.update_bounds();
  return std::move(scene_);
}

}  // namespace scene
