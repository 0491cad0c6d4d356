#include "renderer/gpu_scene.hpp"

#include "renderer/gpu_types.hpp"
#include "renderer/lpv/blocker_surfels.hpp"
#include "renderer/lpv/emitter_surfels.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace renderer {

vkx::VertexInputDesc scene_vertex_input() {
  return {sizeof(scene::Vertex),
          {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
           {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
           {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)}}};
}

GpuScene GpuScene::upload(const vkx::Device& device, const scene::Scene& scene, const TextureSetLayout& texture_layout) {
  GpuScene g;
  std::vector<gpu::GpuMaterial>& materials = g.material_values;
  for (const scene::Material& m : scene.materials) {
    materials.push_back({glm::vec4(m.base_color, 1.0f), glm::vec4(m.emissive, 0.0f),
                         glm::uvec4(m.double_sided ? 1u : 0u, 0u, 0u, 0u)});
    g.emissive = g.emissive || m.emissive != glm::vec3(0.0f);
  }

  g.vertices = vkx::upload_buffer(device, std::as_bytes(std::span(scene.vertices)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  g.indices = vkx::upload_buffer(device, std::as_bytes(std::span(scene.indices)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  g.materials = vkx::upload_buffer(device, std::as_bytes(std::span(materials)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  g.textures = MaterialTextures(device, scene, texture_layout);
  const std::vector<gpu::GpuEmitter> surfels = emitter_surfels(scene);
  g.emitters = vkx::upload_buffer(device, std::as_bytes(std::span(surfels)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  g.emitter_count = std::uint32_t(surfels.size());
  g.emitted_flux = emitted_flux_bound(surfels);
  const std::vector<gpu::GpuBlocker> blockers = blocker_surfels(scene);
  g.blockers = vkx::upload_buffer(device, std::as_bytes(std::span(blockers)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  g.blocker_count = std::uint32_t(blockers.size());
  g.index_count = static_cast<std::uint32_t>(scene.indices.size());
  for (const scene::Material& m : scene.materials)
    g.material_variants.push_back({m.double_sided, m.base_color_texture >= 0 &&
                                                       std::size_t(m.base_color_texture) < scene.textures.size()});
  std::vector<std::size_t> by_variant(scene.draws.size());
  std::iota(by_variant.begin(), by_variant.end(), std::size_t{0});
  std::stable_sort(by_variant.begin(), by_variant.end(), [&](std::size_t a, std::size_t b) {
    return g.material_variants[scene.draws[a].material].index() < g.material_variants[scene.draws[b].material].index();
  });
  for (std::size_t d : by_variant) {
    g.draws.push_back(scene.draws[d]);
    g.draw_bounds.push_back(d < scene.draw_bounds.size() ? scene.draw_bounds[d] : scene.bounds);
  }
  for (const scene::Draw& d : g.draws)
    if (g.variants_in_use.empty() || g.variants_in_use.back().index() != g.material_variants[d.material].index())
      g.variants_in_use.push_back(g.material_variants[d.material]);
  return g;
}

std::vector<std::uint32_t> GpuScene::camera_order(const glm::vec3& eye) const {
  std::vector<float> farthest(draws.size());
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const scene::Bounds& b = draw_bounds[i];
    const glm::vec3 far_corner = glm::max(glm::abs(eye - b.min), glm::abs(eye - b.max));
    farthest[i] = glm::dot(far_corner, far_corner);
  }
  std::vector<std::uint32_t> order(draws.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t va = material_variants[draws[a].material].index();
    const std::uint32_t vb = material_variants[draws[b].material].index();
    return va != vb ? va < vb : farthest[a] < farthest[b];
  });
  return order;
}

std::uint64_t GpuScene::bytes() const {
  return vertices.size() + indices.size() + materials.size() + emitters.size() + blockers.size() + textures.bytes();
}

void GpuScene::bind_geometry(VkCommandBuffer cmd) const {
  const VkDeviceSize offset = 0;
  const VkBuffer vb = vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
}

}  // namespace renderer
