// The forward pass: the camera's view of the scene shaded with direct and indirect light while
// it is rasterised, straight into the 8-bit display image (shaders/forward.frag). It replaces
// the G-buffer and the shading for frames that show the final or direct view and need no
// linear image; the planner decides (plan_shading in frame_plan.hpp).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/material_textures.hpp"
#include "renderer/passes/direct_light_inputs.hpp"
#include "renderer/passes/indirect_light_inputs.hpp"
#include "vkx/pipeline.hpp"

namespace renderer {

class ForwardPass {
 public:
  ForwardPass(const vkx::Device& device, const TextureSetLayout& textures);

  // Draws, in `order` (the scene's camera_order), into targets.display_target and copies it
  // straight into targets.display_readback for the host (the frame's readback has nothing
  // left to copy of it).
  void record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const std::uint32_t> order,
              const FrameTargets& targets, const DirectLightInputs& direct, const IndirectLightInputs& indirect,
              api::Tonemap tone_curve) const;

 private:
  // One pipeline per material variant, specialisation of the light code, cascade count and
  // tone curve, made on first use.
  const vkx::Pipeline& pipeline(MaterialVariant variant, const DirectLightInputs& direct,
                                const IndirectLightInputs& indirect, std::uint32_t curve) const;
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants pipelines_;
  vkx::Sampler shadow_sampler_;  // depth compare: the light code gathers 2x2 comparisons for its PCF
};

}  // namespace renderer
