// The gather transfer for one cascade (lpv_gather.comp, docs/lpv.md "The gather"): every cell
// sums the light of every injected cell along the straight line between them, through the
// geometry volume, into its irradiance cube in the accumulated buffers. It replaces
// propagation when lpv.transfer is "gather". Each bounce after the first is a gather again,
// from the scene's surfels lit by the one before (lpv_gather_bounce.comp), added to the cubes.
#pragma once

#include "api/render_request.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"

#include <cstdint>

namespace renderer {

// The bounces a gather runs (gathered_bounces; the tail: lpv_gather_tail.comp), and what the
// later ones reflect from.
struct GatherBounces {
  GatheredBounces run;
  const vkx::Buffer* surfels = nullptr;  // GpuBlocker: the scene's surfels (bounces after the first)
  std::uint32_t surfel_count = 0;
  api::Injection injection = api::Injection::trilinear;  // how their VPLs are added, as the first's
  bool located_walls = false;  // they read their light past the located walls, as the shading does
};

// How the gather walks its lines of sight: through the geometry volume's blocking or not, its
// far lines per cell or per block (api::FarLines), its faces paired or multiplied along each
// line (api::LineBlocking).
struct GatherLines {
  bool occlusion = true;
  api::FarLines far_lines = api::FarLines::per_block;
  api::LineBlocking blocking = api::LineBlocking::paired;
};

class LpvGatherPass {
 public:
  explicit LpvGatherPass(const vkx::Device& device);

  // Whether the device can walk the far lines once a 2 x 2 x 2 block (api::FarLines::per_block):
  // the block's 8 cells share them by subgroup shuffles, so its subgroups must hold whole
  // blocks (8 lanes or a multiple: lavapipe's 8 on AVX2, GPUs' 16 to 64; not lavapipe's 4).
  static bool shares_far_lines(const vkx::DeviceInfo& device) { return device.subgroup_size % 8 == 0; }

  // Slabs of cells along z (gpu::LPV_GROUP layers each) a bounce of the cascade's gather is
  // recorded in: a render can be stopped between them.
  static std::uint32_t slabs(const LpvVolumes& volumes);

  // Expects the injected sums in volumes.injected and, with lines.occlusion, the geometry volume's
  // faces. Records steps first .. first + count - 1 (0-based; step s is slab s % slabs of
  // bounce s / slabs). A bounce's slab 0 first lists the lit injected cells (in volumes.grids,
  // which the gather does not otherwise use); its last slab is followed by the surfels'
  // reflection of its light into the injected sums, the next bounce's VPLs (or after the last,
  // with bounces.run.tail, by the estimate of the rest).
  void record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count,
              const GatherLines& lines, const GatherBounces& bounces, const vkx::Buffer& params,
              const LpvVolumes& volumes) const;

 private:
  // The pipeline that walks its lines as `lines` says, its descriptor set written for this
  // recording.
  const vkx::Pipeline& variant(const GatherLines& lines, const vkx::Buffer& params, const LpvVolumes& volumes) const;

  // lpv_gather_bounce.comp for these bounces' injection, splatting its VPLs or only summing
  // their flux, its descriptor set written.
  const vkx::Pipeline& reflection(const GatherBounces& bounces, bool splat, const vkx::Buffer& params,
                                  const LpvVolumes& volumes) const;
  // Bounce `bounce` (1-based) done: the injected sums replaced by the surfels' reflection of
  // its light (none without `reflect`), their flux summed into bounce_flux_record(bounce + 1).
  void record_reflection(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t bounce, const GatherBounces& bounces,
                         const vkx::Pipeline* reflect, const LpvVolumes& volumes) const;
  // The estimate of the bounces after the last gathered one: its reflection's flux (`measure`:
  // reflection() without the splat), then lpv_gather_tail.comp, whose set write_tail writes.
  void write_tail(const vkx::Buffer& params, const LpvVolumes& volumes) const;
  void record_tail(VkCommandBuffer cmd, std::uint32_t cascade, const GatherBounces& bounces,
                   const vkx::Pipeline& measure, const LpvVolumes& volumes) const;

  const vkx::Device& device_;
  vkx::Pipeline sources_;  // lpv_gather_sources.comp: the lit injected cells, listed
  vkx::PipelineLayoutDesc bounce_layout_;
  vkx::PipelineVariants bounce_variants_;  // lpv_gather_bounce.comp, by injection and splat
  vkx::Pipeline tail_;                     // lpv_gather_tail.comp
  vkx::PipelineLayoutDesc layout_;
  vkx::PipelineVariants variants_;
};

}  // namespace renderer
