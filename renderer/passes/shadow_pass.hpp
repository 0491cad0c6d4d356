// Shadow maps: the scene's depth from each light, one atlas layer per view
// (spot: one perspective view, point: six cube faces, directional: one orthographic view).
#pragma once

#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "vkx/pipeline.hpp"

#include <glm/mat4x4.hpp>

#include <span>

namespace renderer {

class ShadowPass {
 public:
  explicit ShadowPass(const vkx::Device& device);

  // Renders every view into its layer and leaves the atlas ready for sampling.
  void record(VkCommandBuffer cmd, const GpuScene& scene, const ShadowAtlas& atlas,
              std::span<const glm::mat4> views) const;
  // When the pass does not run: only puts the atlas into the layout the shading expects.
  static void record_skipped(VkCommandBuffer cmd, const ShadowAtlas& atlas);

 private:
  const vkx::Device& device_;
  vkx::Pipeline pipeline_;
};

}  // namespace renderer
