// Reflective shadow maps: for every light view, the surfels the light sees first with their
// position, normal, albedo, area and reflected flux (rsm.frag), one RsmMaps layer per view.
#pragma once

#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/passes/material_pipelines.hpp"

namespace renderer {

class RsmPass {
 public:
  RsmPass(const vkx::Device& device, const TextureSetLayout& textures);

  // Renders every view, each in the corner of its layer its resolution covers (`view_info`,
  // as in `views`: GpuRsmView::info.z texels a side), and leaves the maps in GENERAL layout
  // for the compute passes. `views` holds gpu::GpuRsmView[maps.layers]; `lights` gpu::GpuLight[].
  void record(VkCommandBuffer cmd, const GpuScene& scene, const RsmMaps& maps, const vkx::Buffer& views,
              const std::vector<gpu::GpuRsmView>& view_info, const vkx::Buffer& lights) const;
  // When no light draws the maps but the LPV runs (emissive surfaces alone): the maps the
  // injection and geometry passes bind, made valid for them to bind (never read).
  static void record_skipped(VkCommandBuffer cmd, const RsmMaps& maps);

 private:
  const vkx::Device& device_;
  MaterialPipelines pipelines_;  // by texturing only: both sides of every surface are drawn
};

}  // namespace renderer
