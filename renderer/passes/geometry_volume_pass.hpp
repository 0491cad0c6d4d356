// LPV geometry volume for one cascade: surfels from the RSMs and from the camera's G-buffer
// add one-sided blocking potentials to the cell corners (lpv_geometry_inject.comp); each corner
// keeps its stronger source (lpv_geometry_corners.comp); the corners become the blocking of
// every cell face (lpv_geometry_resolve.comp).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/vulkan/pipeline.hpp"

#include <array>

namespace renderer {

struct GeometrySources {
  bool rsm = true;     // surfels of every RSM texel
  bool camera = true;  // surfels of every camera_stride-th G-buffer pixel (each way)
  std::uint32_t camera_stride = 1;
  api::Injection injection = api::Injection::trilinear;  // to the 8 corners around a surfel, or the nearest
  bool bounces = false;  // the blockers' albedo is splatted and resolved too (it serves bounces only)
};

class GeometryVolumePass {
 public:
  explicit GeometryVolumePass(const vkx::Device& device);

  void record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params, const RsmMaps& maps,
              const FrameTargets& camera, const GeometrySources& sources, const LpvVolumes& volumes) const;

 private:
  const vkx::Device& device_;
  std::array<std::array<vkx::Pipeline, 2>, 2> inject_;  // by GeometrySources::bounces, then api::Injection
  std::array<vkx::Pipeline, 2> corners_;  // by GeometrySources::bounces
  std::array<vkx::Pipeline, 2> resolve_;
};

}  // namespace renderer
