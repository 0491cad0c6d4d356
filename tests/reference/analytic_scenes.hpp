// Scenes and cameras with closed-form answers for the reference renderer's tests, made in
// code. The camera matrices are built here with glm, not by renderer::setup_camera, so the
// tests need nothing of the rasteriser.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "reference/path_tracer.hpp"
#include "scene/scene.hpp"

namespace reference_test {

// A view-projection in Vulkan's clip space (y down, depth 0..1), like the renderer's camera.
glm::mat4 vulkan_view_proj(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fov_y_deg, float aspect, float near,
                           float far);

// A closed sphere of radius `radius` around the origin whose faces and normals point inwards,
// in `rings` x 2*`rings` quads, one Lambertian grey material of albedo `albedo`.
scene::Scene inward_sphere(float radius, float albedo, int rings);

// Appends a single quad with the given corners (counter-clockwise seen from its front), uvs
// and material; its vertex normals are the flat face normal.
void add_quad(scene::Scene& scene, const std::array<glm::vec3, 4>& corners, const std::array<glm::vec2, 4>& uvs,
              std::uint32_t material);

std::uint32_t add_material(scene::Scene& scene, const scene::Material& material);

// Mean over the surface pixels of one channel-averaged image.
double surface_mean(const image::RgbaF32Image& image, const std::vector<std::uint8_t>& mask);

glm::vec3 pixel(const image::RgbaF32Image& image, std::uint32_t x, std::uint32_t y);

}  // namespace reference_test
