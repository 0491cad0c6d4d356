// Direct and indirect lighting (and the data views) from the G-buffer into the frame's
// linear image.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/vulkan/pipeline.hpp"

#include <array>
#include <memory>

namespace renderer {

struct ShadeInputs {
  const vkx::Buffer& frame;         // gpu::GpuFrame
  const vkx::Buffer& lights;        // gpu::GpuLight[]
  const vkx::Buffer& shadow_views;  // mat4[] per atlas layer
  const ShadowAtlas& atlas;
  const vkx::Buffer& lpv;          // gpu::GpuLpv (cascade count 0: no indirect light)
  const LpvVolumes& volumes;       // the cascades' accumulated SH (not read without indirect light)
  bool indirect;                   // the LPV ran: shade its indirect light
  std::uint32_t view;              // gpu::VIEW_*
};

class ShadePass {
 public:
  explicit ShadePass(const vkx::Device& device);

  // Writes targets.linear and makes it visible to later compute and transfer reads.
  void record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets, const ShadeInputs& in) const;

 private:
  // One shader specialised by what the frame shows (lavapipe runs both sides of a branch):
  // index view * 2 + indirect; made on first use, the two final frames at start.
  const vkx::Pipeline& variant(std::uint32_t view, bool indirect) const;
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc layout_;
  mutable std::array<std::unique_ptr<vkx::Pipeline>, 2 * gpu::VIEW_COUNT> variants_;
  vkx::Sampler shadow_sampler_;  // depth compare with bilinear 2x2 PCF
};

}  // namespace renderer
