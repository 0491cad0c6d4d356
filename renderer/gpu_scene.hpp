// A scene's geometry and materials resident on the device: uploaded once, drawn by many frames.
#pragma once

#include "renderer/scene/scene.hpp"
#include "renderer/vulkan/resources.hpp"

#include <vector>

namespace renderer {

struct GpuScene {
  vkx::Buffer vertices;   // scene::Vertex
  vkx::Buffer indices;    // uint32
  vkx::Buffer materials;  // gpu::GpuMaterial
  std::uint32_t index_count = 0;
  std::vector<scene::Draw> draws;

  static GpuScene upload(const vkx::Device& device, const scene::Scene& scene);

  // Device memory held.
  std::uint64_t bytes() const;

  // Binds the vertex and index buffers for drawing.
  void bind_geometry(VkCommandBuffer cmd) const;
};

}  // namespace renderer
