// The camera's G-buffer: world position with material id, normal and albedo per pixel.
// Back faces are culled: scene surfaces are one-sided.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/vulkan/pipeline.hpp"

namespace renderer {

class GBufferPass {
 public:
  explicit GBufferPass(const vkx::Device& device);

  // `frame` holds a gpu::GpuFrame. Leaves the colour targets ready for compute sampling.
  void record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets, const vkx::Buffer& frame) const;

 private:
  const vkx::Device& device_;
  vkx::Pipeline pipeline_;
};

}  // namespace renderer
