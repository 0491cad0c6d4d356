#include "renderer/passes/lpv_inject_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "shaders/shared/lpv_inject_interface.h"
#include "shaders/lpv_inject.comp.h"
#include "shaders/lpv_inject_emitters.comp.h"
#include "shaders/lpv_inject_resolve.comp.h"

#include <array>

namespace renderer {


namespace {

// Whether two VPLs of the view may lie close enough to merge (lpv_inject.comp): a 2 x 2 quad
// once merged spans at most 1 / LPV_VPLS_PER_CELL_SIDE of a cell. An orthographic view's
// texels are footprint apart on a surface facing it, and further on any other; a perspective
// view's come as close as the surfaces come to its light.
bool may_merge(const gpu::GpuRsmView& view, const api::Lpv& lpv, float cell_size) {
  if (view.info.y != gpu::RSM_VIEW_ORTHOGRAPHIC) return true;
  const float spacing = view.axis.w * float(lpv.vpl_downsample);
  return 2.0f * spacing * float(gpu::LPV_VPLS_PER_CELL_SIDE) <= cell_size;
}

}  // namespace

LpvInjectPass::LpvInjectPass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  inject_layout_ = vkx::compute_layout({{gpu::INJECT_LPV, uniform},
                                        {gpu::INJECT_RSM_POSITION, image},
                                        {gpu::INJECT_RSM_NORMAL, image},
                                        {gpu::INJECT_RSM_FLUX, image},
                                        {gpu::INJECT_INJECTED, buffer},
                                        {gpu::INJECT_FLUX_STATS, buffer},
                                        {gpu::INJECT_WALLS, texels}},
                                       sizeof(gpu::LpvInjectRsmPush));
  emitters_layout_ = vkx::compute_layout({{gpu::INJECT_EMITTERS_LPV, uniform},
                                          {gpu::INJECT_EMITTERS_EMITTERS, buffer},
                                          {gpu::INJECT_EMITTERS_INJECTED, buffer},
                                          {gpu::INJECT_EMITTERS_FLUX_STATS, buffer}},
                                         sizeof(gpu::LpvInjectEmittersPush));
  resolve_ = vkx::Pipeline(device,
                           vkx::compute_layout({{gpu::INJECT_RESOLVE_LPV, uniform},
                                                {gpu::INJECT_RESOLVE_INJECTED, texels},
                                                {gpu::INJECT_RESOLVE_GRIDS, buffer},
                                                {gpu::INJECT_RESOLVE_ACCUMULATED_R, buffer},
                                                {gpu::INJECT_RESOLVE_ACCUMULATED_G, buffer},
                                                {gpu::INJECT_RESOLVE_ACCUMULATED_B, buffer},
                                                {gpu::INJECT_RESOLVE_FLUX_STATS, buffer}},
                                               sizeof(gpu::LpvInjectPush)),
                           spirv_lpv_inject_resolve_comp);
}

void LpvInjectPass::record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params, const RsmMaps* maps,
                           const std::vector<gpu::GpuRsmView>& views, const api::Lpv& lpv, float cell_size,
                           const GpuScene& scene, const LpvVolumes& volumes, bool located_walls) const {
  const std::array<std::uint32_t, 1> trilinear{lpv.injection == api::Injection::trilinear ? 1u : 0u};
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  // The sums start at zero in every cascade (a fill is a memset; the resolve's stores, lane by
  // lane, cost more).
  if (cascade == 0) vkCmdFillBuffer(cmd, volumes.flux_stats.handle(), 0, VK_WHOLE_SIZE, 0);
  vkCmdFillBuffer(cmd, volumes.injected.buffer().handle(), 0, VK_WHOLE_SIZE, 0);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  if (maps) {
    // By constant_id: TRILINEAR_INJECTION (0), LOCATED_WALLS (1).
    const std::array<std::uint32_t, 2> constants{trilinear[0], located_walls ? 1u : 0u};
    const vkx::Pipeline& inject = inject_.get(constants[0] | constants[1] << 1, [&] {
      return vkx::Pipeline(device_, inject_layout_, spirv_lpv_inject_comp, constants);
    });
    vkx::DescriptorWriter(inject.descriptor_set())
        .buffer(gpu::INJECT_LPV, uniform, params.handle())
        .image(gpu::INJECT_RSM_POSITION, image, maps->position.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(gpu::INJECT_RSM_NORMAL, image, maps->normal.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(gpu::INJECT_RSM_FLUX, image, maps->flux.view(), VK_IMAGE_LAYOUT_GENERAL)
        .buffer(gpu::INJECT_INJECTED, storage, volumes.injected.buffer().handle())
        .buffer(gpu::INJECT_FLUX_STATS, storage, volumes.flux_stats.handle())
        .texel_buffer(gpu::INJECT_WALLS, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, volumes.walls.view())
        .apply(device_.handle());
    inject.bind(cmd);
    for (std::uint32_t layer = 0; layer < maps->layers && layer < views.size(); ++layer) {
      const std::uint32_t vpls_per_side = vpls_per_view_side(views[layer], lpv);
      const bool merge = may_merge(views[layer], lpv, cell_size);
      inject.push(cmd, gpu::LpvInjectRsmPush{cascade, volumes.vpl_flux_record(cascade), layer, vpls_per_side, merge});
      // An invocation a tile, or a VPL.
      const std::uint32_t side = merge ? vkx::group_count(vpls_per_side, gpu::LPV_INJECT_TILE) : vpls_per_side;
      const std::uint32_t groups = vkx::group_count(side, gpu::LPV_VPL_GROUP);
      vkCmdDispatch(cmd, groups, groups, 1);
    }
  }
  if (scene.emitter_count) {  // after the RSM's VPLs: both add to the same integer sums
    const vkx::Pipeline& emitters = emitters_.get(trilinear[0], [&] {
      return vkx::Pipeline(device_, emitters_layout_, spirv_lpv_inject_emitters_comp, trilinear);
    });
    vkx::DescriptorWriter(emitters.descriptor_set())
        .buffer(gpu::INJECT_EMITTERS_LPV, uniform, params.handle())
        .buffer(gpu::INJECT_EMITTERS_EMITTERS, storage, scene.emitters.handle())
        .buffer(gpu::INJECT_EMITTERS_INJECTED, storage, volumes.injected.buffer().handle())
        .buffer(gpu::INJECT_EMITTERS_FLUX_STATS, storage, volumes.flux_stats.handle())
        .apply(device_.handle());
    if (maps) vkx::compute_barrier(cmd);
    emitters.bind(cmd);
    emitters.push(cmd, gpu::LpvInjectEmittersPush{cascade, volumes.vpl_flux_record(cascade), scene.emitter_count});
    vkCmdDispatch(cmd, vkx::group_count(scene.emitter_count, gpu::LPV_EMITTER_GROUP), 1, 1);
  }
  vkx::compute_barrier(cmd);
  vkx::DescriptorWriter(resolve_.descriptor_set())
      .buffer(gpu::INJECT_RESOLVE_LPV, uniform, params.handle())
      .texel_buffer(gpu::INJECT_RESOLVE_INJECTED, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, volumes.injected.view())
      .buffer(gpu::INJECT_RESOLVE_GRIDS, storage, volumes.grids.buffer().handle())
      .buffer(gpu::INJECT_RESOLVE_ACCUMULATED_R, storage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::INJECT_RESOLVE_ACCUMULATED_G, storage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::INJECT_RESOLVE_ACCUMULATED_B, storage, volumes.accumulated[2].buffer().handle())
      .buffer(gpu::INJECT_RESOLVE_FLUX_STATS, storage, volumes.flux_stats.handle())
      .apply(device_.handle());
  resolve_.bind(cmd);
  resolve_.push(cmd, gpu::LpvInjectPush{cascade, volumes.grid_flux_record(cascade, 0)});
  const glm::uvec3 d = volumes.dims;
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), vkx::group_count(d.z, gpu::LPV_GROUP));
  vkx::compute_barrier(cmd);
}

}  // namespace renderer
