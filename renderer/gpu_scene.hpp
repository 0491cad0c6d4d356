// A scene's geometry and materials resident on the device: uploaded once, drawn by many frames.
#pragma once

#include "renderer/material_textures.hpp"
#include "renderer/scene/scene.hpp"
#include "renderer/vulkan/resources.hpp"

#include <vector>

namespace renderer {

struct GpuScene {
  vkx::Buffer vertices;   // scene::Vertex
  vkx::Buffer indices;    // uint32
  vkx::Buffer materials;  // gpu::GpuMaterial
  MaterialTextures textures;
  vkx::Buffer emitters;  // gpu::GpuEmitter: the emissive surfaces as VPLs
  std::uint32_t emitter_count = 0;
  double emitted_flux = 0.0;  // the largest channel of their summed flux (W)
  std::uint32_t index_count = 0;
  std::vector<scene::Draw> draws;

  static GpuScene upload(const vkx::Device& device, const scene::Scene& scene, const TextureSetLayout& texture_layout);

  // Device memory held.
  std::uint64_t bytes() const;

  // Binds the vertex and index buffers for drawing.
  void bind_geometry(VkCommandBuffer cmd) const;
  // Draws every draw of the scene with `pipeline`, its material's texture bound as set 1;
  // `push(draw)` sets the draw's push constants first.
  template <typename Push>
  void draw_all(VkCommandBuffer cmd, VkPipelineLayout pipeline_layout, Push push) const {
    for (const scene::Draw& draw : draws) {
      const VkDescriptorSet set = textures.set_of(draw.material);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_layout, 1, 1, &set, 0, nullptr);
      push(draw);
      vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, 0, 0);
    }
  }
};

}  // namespace renderer
