// The gather transfer for one cascade (lpv_gather.comp, docs/lpv.md "The gather"): every cell
// sums the light of every injected cell along the straight line between them, through the
// geometry volume, into its irradiance cube in the accumulated buffers. It replaces
// propagation when lpv.transfer is "gather".
#pragma once

#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"

#include <cstdint>

namespace renderer {

class LpvGatherPass {
 public:
  explicit LpvGatherPass(const vkx::Device& device);

  // Slabs of cells along z (gpu::LPV_GROUP layers each) the cascade's gather is recorded in:
  // a render can be stopped between them.
  static std::uint32_t slabs(const LpvVolumes& volumes);

  // Expects the injected sums in volumes.injected and, when `occlusion`, the geometry volume's
  // faces. Records slabs first .. first + count - 1 (0-based); slab 0 first lists the lit
  // injected cells (in volumes.grids, which the gather does not otherwise use).
  void record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count, bool occlusion,
              const vkx::Buffer& params, const LpvVolumes& volumes) const;

 private:
  // The pipeline with or without blocking, its descriptor set written for this recording.
  const vkx::Pipeline& variant(bool occlusion, const vkx::Buffer& params, const LpvVolumes& volumes) const;

  const vkx::Device& device_;
  vkx::Pipeline sources_;  // lpv_gather_sources.comp: the lit injected cells, listed
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants variants_;
};

}  // namespace renderer
