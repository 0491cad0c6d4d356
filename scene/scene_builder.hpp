// Builds scenes from quads and boxes: the built-in scenes and the tests' analytic setups.
// Faces are one-sided: their normal is the side that is shaded and counter-clockwise.
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace scene {

class SceneBuilder {
 public:
  explicit SceneBuilder(std::string name);

  std::uint32_t add_material(const Material& material);

  // A planar quad with corners p0, p1, p2, p3 in counter-clockwise order seen from its front.
  void add_quad(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, std::uint32_t material);
  // A square quad of side `size` centred at `center`, facing `normal`.
  void add_facing_quad(glm::vec3 center, glm::vec3 normal, float size, std::uint32_t material);
  // A closed box with outward faces, rotated by `yaw_deg` about +Y around its base centre.
  void add_box(glm::vec3 base_center, glm::vec3 size, float yaw_deg, std::uint32_t material);

  void add_light(const api::Light& light) { scene_.lights.push_back(light); }
  void set_camera(const api::Camera& camera) { scene_.camera = camera; }

  Scene build();

 private:
  Scene scene_;
};

}  // namespace scene
