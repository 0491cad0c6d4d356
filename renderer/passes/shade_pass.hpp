// Direct and indirect lighting (and the data views) from the G-buffer into the frame's
// linear image, its display-encoded 8-bit image, or both.
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/passes/direct_light_inputs.hpp"
#include "renderer/passes/indirect_light_inputs.hpp"
#include "vkx/pipeline.hpp"

#include <cstdint>

namespace renderer {

struct ShadeInputs {
  DirectLightInputs direct;        // views without direct light: no light kinds, count 0
  IndirectLightInputs indirect;
  std::uint32_t view;              // gpu::VIEW_*
  std::uint32_t outputs;           // gpu::SHADE_OUTPUT_* bits: the images to write
  api::Tonemap tone_curve;         // of the display image
};

class ShadePass {
 public:
  explicit ShadePass(const vkx::Device& device);

  // Writes targets.linear and/or targets.display, as in.outputs asks, and makes them visible
  // to later compute and transfer reads. The display image is tone-mapped (in.tone_curve) and
  // sRGB-encoded for the lit views, quantised linearly for the data views (normal, depth).
  void record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets, const ShadeInputs& in) const;

 private:
  // One shader specialised by what the frame shows, the kinds of light it has and the images
  // it writes (lavapipe runs both sides of a branch, so code that cannot apply would cost
  // every pixel); made on first use.
  const vkx::Pipeline& variant(const ShadeInputs& in) const;
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants variants_;
  vkx::Sampler shadow_sampler_;  // depth compare: the shading gathers 2x2 comparisons for its PCF
};

}  // namespace renderer
