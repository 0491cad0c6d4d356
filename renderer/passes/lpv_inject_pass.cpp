#include "renderer/passes/lpv_inject_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_inject_interface.h"
#include "shaders/lpv_inject.comp.h"
#include "shaders/lpv_inject_emitters.comp.h"
#include "shaders/lpv_inject_resolve.comp.h"

#include <array>

namespace renderer {


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
                                        {gpu::INJECT_FLUX_STATS, buffer}},
                                       sizeof(gpu::LpvInjectPush));
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
                           std::uint32_t vpls_per_side, const GpuScene& scene, const LpvVolumes& volumes,
                           api::Injection injection) const {
  const std::array<std::uint32_t, 1> trilinear{injection == api::Injection::trilinear ? 1u : 0u};
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
    const vkx::Pipeline& inject = inject_.get(
        trilinear[0], [&] { return vkx::Pipeline(device_, inject_layout_, spirv_lpv_inject_comp, trilinear); });
    vkx::DescriptorWriter(inject.descriptor_set())
        .buffer(gpu::INJECT_LPV, uniform, params.handle())
        .image(gpu::INJECT_RSM_POSITION, image, maps->position.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(gpu::INJECT_RSM_NORMAL, image, maps->normal.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(gpu::INJECT_RSM_FLUX, image, maps->flux.view(), VK_IMAGE_LAYOUT_GENERAL)
        .buffer(gpu::INJECT_INJECTED, storage, volumes.injected.buffer().handle())
        .buffer(gpu::INJECT_FLUX_STATS, storage, volumes.flux_stats.handle())
        .apply(device_.handle());
    inject.bind(cmd);
    inject.push(cmd, gpu::LpvInjectPush{cascade, volumes.vpl_flux_record(cascade)});
    const std::uint32_t groups = vkx::group_count(vpls_per_side, gpu::LPV_VPL_GROUP);
    vkCmdDispatch(cmd, groups, groups, maps->layers);
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
