// Direct and indirect lighting (and the data views) from the G-buffer into the frame's
// linear image.
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/vulkan/pipeline.hpp"

#include <cstdint>
#include <span>

namespace renderer {

struct ShadeInputs {
  const vkx::Buffer& frame;         // gpu::GpuFrame
  const vkx::Buffer& lights;        // gpu::GpuLight[]
  const vkx::Buffer& shadow_views;  // mat4[] per atlas layer
  const ShadowAtlas& atlas;
  const vkx::Buffer& lpv;          // gpu::GpuLpv
  const LpvVolumes& volumes;       // the cascades' accumulated SH (not read without indirect light)
  std::uint32_t cascades;          // of indirect light to shade (0: the LPV did not run)
  std::uint32_t view;              // gpu::VIEW_*
  std::uint32_t light_kinds;       // gpu::LIGHTS_* bits (light_kinds())
  std::uint32_t light_count;       // of the buffer `lights`
};

// The gpu::LIGHTS_* bits that describe what `lights`, and emissive materials if the scene
// has any, need of the shading.
std::uint32_t light_kinds(std::span<const gpu::GpuLight> lights, bool emissive_materials);

class ShadePass {
 public:
  explicit ShadePass(const vkx::Device& device);

  // Writes targets.linear and makes it visible to later compute and transfer reads.
  void record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets, const ShadeInputs& in) const;

 private:
  // One shader specialised by what the frame shows and the kinds of light it has (lavapipe
  // runs both sides of a branch, so code that cannot apply would cost every pixel); made on
  // first use.
  const vkx::Pipeline& variant(const ShadeInputs& in) const;
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants variants_;
  vkx::Sampler shadow_sampler_;  // depth compare: the shading gathers 2x2 comparisons for its PCF
};

}  // namespace renderer
