// Direct and indirect lighting (and the data views) from the G-buffer into the frame's
// linear image.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/vulkan/pipeline.hpp"

namespace renderer {

struct ShadeInputs {
  const vkx::Buffer& frame;         // gpu::GpuFrame
  const vkx::Buffer& lights;        // gpu::GpuLight[]
  const vkx::Buffer& shadow_views;  // mat4[] per atlas layer
  const ShadowAtlas& atlas;
  const vkx::Buffer& lpv;          // gpu::GpuLpv (cascade count 0: no indirect light)
  const vkx::Buffer& accumulated;  // the cascades' accumulated SH (any buffer when there are none)
};

class ShadePass {
 public:
  explicit ShadePass(const vkx::Device& device);
  ~ShadePass();
  ShadePass(const ShadePass&) = delete;
  ShadePass& operator=(const ShadePass&) = delete;

  // Writes targets.linear and makes it visible to later compute and transfer reads.
  void record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets, const ShadeInputs& in) const;

 private:
  const vkx::Device& device_;
  vkx::Pipeline pipeline_;
  VkSampler shadow_sampler_ = VK_NULL_HANDLE;  // depth compare with bilinear 2x2 PCF
};

}  // namespace renderer
