// The frame's linear image to 8-bit RGBA for PNG: tone curve, clamp, sRGB encoding.
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/vulkan/pipeline.hpp"

namespace renderer {

class TonemapPass {
 public:
  explicit TonemapPass(const vkx::Device& device);

  // `display_encode`: tone curve and sRGB for pictures; false quantises data views linearly.
  void record(VkCommandBuffer cmd, const FrameTargets& targets, api::Tonemap curve, bool display_encode) const;

 private:
  const vkx::Device& device_;
  vkx::Pipeline pipeline_;
};

}  // namespace renderer
