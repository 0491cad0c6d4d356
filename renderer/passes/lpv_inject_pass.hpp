// LPV injection for one cascade: the RSM texels, merged into VPLs, and the emissive surfels
// become fixed-point SH in the cells around each, or the one it lands in, as lpv.injection
// says (lpv_inject.comp, lpv_inject_emitters.comp);
// the sums then become the float grid propagation starts from and the first term of the
// accumulated light (lpv_inject_resolve.comp).
#pragma once

#include "api/render_request.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"

namespace renderer {

class LpvInjectPass {
 public:
  explicit LpvInjectPass(const vkx::Device& device);

  // `params` is the frame's gpu::GpuLpv; `maps` are the frame's RSMs, nullptr when no light
  // drew any, one layer per view of `views` (each its own resolution); `cell_size` the
  // cascade's. The first cascade also clears the flux statistics. `located_walls`: the RSMs'
  // VPLs see their cells past the geometry volume's located walls (lpv_walls.glsl), which it
  // built for this cascade before.
  void record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params, const RsmMaps* maps,
              const std::vector<gpu::GpuRsmView>& views, const api::Lpv& lpv, float cell_size, const GpuScene& scene,
              const LpvVolumes& volumes, bool located_walls) const;

 private:
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc inject_layout_, emitters_layout_;
  // Made on first use (lavapipe compiles each), by api::Injection: a scene without emissive
  // surfaces never compiles the emitters' shader.
  vkx::PipelineVariants inject_, emitters_;
  vkx::Pipeline resolve_;
};

}  // namespace renderer
