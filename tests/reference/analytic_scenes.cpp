#include "analytic_scenes.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace reference_test {

glm::mat4 vulkan_view_proj(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fov_y_deg, float aspect, float near,
                           float far) {
  glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(fov_y_deg), aspect, near, far);
  projection[1][1] *= -1.0f;
  return projection * glm::lookAtRH(eye, target, up);
}

std::uint32_t add_material(scene::Scene& scene, const scene::Material& material) {
  scene.materials.push_back(material);
  return std::uint32_t(scene.materials.size() - 1);
}

void add_quad(scene::Scene& scene, const std::array<glm::vec3, 4>& corners, const std::array<glm::vec2, 4>& uvs,
              std::uint32_t material) {
  const glm::vec3 n = glm::normalize(glm::cross(corners[1] - corners[0], corners[3] - corners[0]));
  const auto base = std::uint32_t(scene.vertices.size());
  for (int i = 0; i < 4; ++i) scene.vertices.push_back({corners[i], n, uvs[i]});
  const auto first = std::uint32_t(scene.indices.size());
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(base + i);
  scene.draws.push_back({first, 6, material});
  scene.update_bounds();
}

scene::Scene inward_sphere(float radius, float albedo, int rings) {
  scene::Scene s;
  s.name = "inward-sphere";
  add_material(s, {"grey", glm::vec3(albedo), {}});
  const int segments = 2 * rings;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double theta = pi * i / rings, phi = 2.0 * pi * j / segments;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      s.vertices.push_back({glm::vec3(d * double(radius)), glm::vec3(-d), glm::vec2(0.0f)});
    }
  auto at = [&](int i, int j) { return std::uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // Counter-clockwise seen from inside (from the origin); the pole rows' degenerate
      // halves have no area and are dropped by the tracer like the rasteriser drops them.
      for (std::uint32_t v : {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
        s.indices.push_back(v);
    }
  s.draws.push_back({0, std::uint32_t(s.indices.size()), 0});
  s.update_bounds();
  return s;
}

double surface_mean(const image::RgbaF32Image& image, const std::vector<std::uint8_t>& mask) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      sum += (double(image.pixels[i * 4]) + image.pixels[i * 4 + 1] + image.pixels[i * 4 + 2]) / 3.0;
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

glm::vec3 pixel(const image::RgbaF32Image& image, std::uint32_t x, std::uint32_t y) {
  const float* p = &image.pixels[(std::size_t(y) * image.width + x) * 4];
  return {p[0], p[1], p[2]};
}

}  // namespace reference_test
