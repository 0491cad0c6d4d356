#include "renderer/gpu_scene.hpp"

#include "renderer/gpu_types.hpp"
#include "renderer/lpv/emitter_surfels.hpp"

#include <algorithm>
#include <cstddef>

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
  g.index_count = static_cast<std::uint32_t>(scene.indices.size());
  for (const scene::Material& m : scene.materials)
    g.material_variants.push_back({m.double_sided, m.base_color_texture >= 0 &&
                                                       std::size_t(m.base_color_texture) < scene.textures.size()});
  g.draws = scene.draws;
  std::stable_sort(g.draws.begin(), g.draws.end(), [&](const scene::Draw& a, const scene::Draw& b) {
    return g.material_variants[a.material].index() < g.material_variants[b.material].index();
  });
  for (const scene::Draw& d : g.draws)
    if (g.variants_in_use.empty() || g.variants_in_use.back().index() != g.material_variants[d.material].index())
      g.variants_in_use.push_back(g.material_variants[d.material]);
  return g;
}

std::uint64_t GpuScene::bytes() const {
  return vertices.size() + indices.size() + materials.size() + emitters.size() + textures.bytes();
}

void GpuScene::bind_geometry(VkCommandBuffer cmd) const {
  const VkDeviceSize offset = 0;
  const VkBuffer vb = vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
}

}  // namespace renderer
