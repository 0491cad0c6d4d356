// LPV geometry volume for one cascade: surfels from the RSMs and from the camera's surfel
// G-buffer (FrameTargets::surfels, drawn by the GBufferPass) add one-sided blocking
// potentials to the cell corners (lpv_geometry_inject.comp); each corner keeps its stronger
// source (lpv_geometry_corners.comp); the corners become the blocking of every cell face
// (lpv_geometry_resolve.comp).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/vulkan/pipeline.hpp"

namespace renderer {

struct GeometrySources {
  bool rsm = true;     // surfels of every rsm_stride-th RSM texel (each way)
  bool camera = true;  // surfels of every texel of the camera's surfel G-buffer
  std::uint32_t rsm_stride = 1;
  api::Injection injection = api::Injection::trilinear;  // to the 8 corners around a surfel, or the nearest
  bool bounces = false;  // the blockers' albedo is splatted and resolved too (it serves bounces only)
};

class GeometryVolumePass {
 public:
  explicit GeometryVolumePass(const vkx::Device& device);

  void record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params, const RsmMaps& maps,
              const GBuffer& camera_surfels, const GeometrySources& sources, const LpvVolumes& volumes) const;

 private:
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc inject_layout_, corners_layout_, resolve_layout_;
  // Made on first use (lavapipe compiles each): inject_ by bounces and injection, the others
  // by bounces.
  vkx::PipelineVariants inject_, corners_, resolve_;
};

}  // namespace renderer
