// The camera's G-buffer: world position with material id, normal and albedo (base colour
// times texture) per pixel. Back faces of one-sided materials are culled; those of
// double-sided ones are drawn with their normal flipped.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/passes/material_pipelines.hpp"

namespace renderer {

class GBufferPass {
 public:
  GBufferPass(const vkx::Device& device, const TextureSetLayout& textures);

  // `frame` holds a gpu::GpuFrame; `order`: the scene's camera_order. Leaves the colour
  // targets ready for compute sampling.
  void record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const std::uint32_t> order,
              const FrameTargets& targets, const vkx::Buffer& frame) const;

 private:
  const vkx::Device& device_;
  MaterialPipelines pipelines_;
};

}  // namespace renderer
