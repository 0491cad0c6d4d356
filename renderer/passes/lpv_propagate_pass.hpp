// LPV propagation for one cascade: N gather iterations (lpv_propagate.comp), each adding its
// result to the cascade's accumulated light.
#pragma once

#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"

namespace renderer {

class LpvPropagatePass {
 public:
  // `column_length`: cells each invocation walks along z; 0 chooses by device (the .cpp says how).
  LpvPropagatePass(const vkx::Device& device, std::uint32_t column_length = 0);

  // Expects the injected grid in the first half of volumes.grids, and the geometry volume's
  // faces when `occlusion` (they block light; with `bounces`, they reflect what they block).
  // Records iterations first .. first + count - 1 (1-based: the ping-pong halves and the
  // start of occlusion follow the iteration number, so a propagation may be cut in chunks).
  void record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count, bool occlusion,
              bool bounces, const vkx::Buffer& params, const LpvVolumes& volumes) const;

 private:
  enum Variant { kOpen, kOccluded, kOccludedBounces };
  // The pipeline specialised for one variant, its descriptor set written for this recording
  // (made on first use: a frame without occlusion never compiles the occluded shader).
  const vkx::Pipeline& variant(Variant v, const vkx::Buffer& params, const LpvVolumes& volumes) const;

  const vkx::Device& device_;
  std::uint32_t column_length_;  // the shader's COLUMN_LENGTH
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants variants_;
};

}  // namespace renderer
