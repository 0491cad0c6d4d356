// Direct and indirect lighting (and the data views) from the G-buffer into the frame's
// linear image, its display-encoded 8-bit image, or both.
#pragma once

#include "api/render_request.hpp"
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
  std::uint32_t outputs;           // gpu::SHADE_OUTPUT_* bits: the images to write
  api::Tonemap tone_curve;         // of the display image
};

// The gpu::LIGHTS_* bits that describe what `lights`, and emissive materials if the scene
// has any, need of the shading.
std::uint32_t light_kinds(std::span<const gpu::GpuLight> lights, bool emissive_materials);

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
