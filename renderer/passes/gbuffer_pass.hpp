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

  // Draws the camera's view into `target` through its viewport. `frame` holds a
  // gpu::GpuFrame; `order`: the scene's camera_order. Leaves the colour targets ready for
  // compute reads.
  void record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const std::uint32_t> order, const GBuffer& target,
              const vkx::Buffer& frame) const;
  // Leaves `target`'s colour images, not drawn this frame, in the layout compute passes bind
  // them with (their contents undefined: no pass reads them then).
  static void record_unused(VkCommandBuffer cmd, const GBuffer& target);

 private:
  const vkx::Device& device_;
  MaterialPipelines pipelines_;
};

}  // namespace renderer
