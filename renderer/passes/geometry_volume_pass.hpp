// LPV geometry volume for one cascade: the scene's surfaces (GpuScene::blockers), surfels
// from the RSMs or from the camera's surfel G-buffer (FrameTargets::surfels, drawn by the
// GBufferPass) add blocking potentials to the cell corners (lpv_geometry_inject.comp); each
// corner keeps its strongest source (lpv_geometry_corners.comp); the corners become the
// blocking of every cell face (lpv_geometry_resolve.comp).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "vkx/pipeline.hpp"

#include <algorithm>
#include <string>

namespace renderer {

struct GeometrySources {
  bool rsm = false;     // surfels of every few RSM texels (each way: GpuRsmView::info.w)
  bool camera = false;  // surfels of every texel of the camera's surfel G-buffer
  bool scene = true;    // the scene's surfaces, cut into pieces (GpuScene::blockers)
  api::Injection injection = api::Injection::trilinear;  // to the 8 corners around a surfel, or the nearest
  bool bounces = false;  // the blockers' albedo is splatted and resolved too (it serves bounces only)
  bool covers = false;   // the faces' cover texels are resolved too (the gather's paired faces read them)
  bool walls = false;    // the walls about the faces are located too (the shading reads them: lpv_walls.h)

  // Slots of corner sums, one per source used (at least one), and the slot of `source`
  // (gpu::LPV_GV_SOURCE_*): the sources' sums are kept apart so each corner can keep the
  // strongest, and a frame pays in memory only for the sources it uses.
  std::uint32_t slots() const {
    return std::max(1u, std::uint32_t(rsm) + std::uint32_t(camera) + std::uint32_t(scene));
  }
  std::uint32_t slot(std::uint32_t source) const {
    const bool used[gpu::LPV_GV_SOURCES] = {rsm, camera, scene};
    std::uint32_t s = 0;
    for (std::uint32_t k = 0; k < source; ++k) s += used[k] ? 1u : 0u;
    return s;
  }
};

// The sources and splatting a request asks for, the RSMs only where the frame draws them
// (`rsm_drawn`); the renderer adds bounces.
GeometrySources geometry_sources(const api::Lpv& lpv, bool rsm_drawn = true);

// What the volume is made of, for the stats: "occluders: the scene's surfaces (19800 pieces)
// and the camera's surfels". `blockers`: the scene's pieces (GpuScene::blocker_count).
std::string describe_occluders(const GeometrySources& sources, std::uint32_t blockers);

class GeometryVolumePass {
 public:
  explicit GeometryVolumePass(const vkx::Device& device);

  // `rsm_views`: the RSMs' light views, a layer each (their resolutions and surfel strides).
  void record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params, const RsmMaps& maps,
              const std::vector<gpu::GpuRsmView>& rsm_views, const GBuffer& camera_surfels, const GpuScene& scene,
              const GeometrySources& sources, const LpvVolumes& volumes) const;

 private:
  const vkx::Device& device_;
  vkx::PipelineLayoutDesc inject_layout_, corners_layout_, resolve_layout_;
  // Made on first use (lavapipe compiles each): inject_ by bounces and injection, the others
  // by bounces.
  vkx::PipelineVariants inject_, corners_, resolve_;
};

}  // namespace renderer
