#include "renderer/passes/lpv_inject_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/lpv_inject.comp.h"
#include "shaders/lpv_inject_emitters.comp.h"
#include "shaders/lpv_inject_resolve.comp.h"

#include <array>

namespace renderer {
namespace {

struct CascadeConstants {
  std::uint32_t cascade;
  std::uint32_t stats_record;
};

struct EmitterConstants {
  std::uint32_t cascade;
  std::uint32_t stats_record;
  std::uint32_t count;
};

}  // namespace

LpvInjectPass::LpvInjectPass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const std::uint32_t push = sizeof(CascadeConstants);
  inject_layout_ = vkx::compute_layout({uniform, image, image, image, buffer, buffer}, push);
  emitters_layout_ = vkx::compute_layout({uniform, buffer, buffer, buffer}, sizeof(EmitterConstants));
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  resolve_ = vkx::Pipeline(device, vkx::compute_layout({uniform, texels, buffer, buffer, buffer, buffer, buffer}, push),
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
        .buffer(0, uniform, params.handle())
        .image(1, image, maps->position.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(2, image, maps->normal.view(), VK_IMAGE_LAYOUT_GENERAL)
        .image(3, image, maps->flux.view(), VK_IMAGE_LAYOUT_GENERAL)
        .buffer(4, storage, volumes.injected.buffer().handle())
        .buffer(5, storage, volumes.flux_stats.handle())
        .apply(device_.handle());
    inject.bind(cmd);
    inject.push(cmd, CascadeConstants{cascade, volumes.vpl_flux_record(cascade)});
    const std::uint32_t groups = vkx::group_count(vpls_per_side, gpu::LPV_VPL_GROUP);
    vkCmdDispatch(cmd, groups, groups, maps->layers);
  }
  if (scene.emitter_count) {  // after the RSM's VPLs: both add to the same integer sums
    const vkx::Pipeline& emitters = emitters_.get(trilinear[0], [&] {
      return vkx::Pipeline(device_, emitters_layout_, spirv_lpv_inject_emitters_comp, trilinear);
    });
    vkx::DescriptorWriter(emitters.descriptor_set())
        .buffer(0, uniform, params.handle())
        .buffer(1, storage, scene.emitters.handle())
        .buffer(2, storage, volumes.injected.buffer().handle())
        .buffer(3, storage, volumes.flux_stats.handle())
        .apply(device_.handle());
    if (maps) vkx::compute_barrier(cmd);
    emitters.bind(cmd);
    emitters.push(cmd, EmitterConstants{cascade, volumes.vpl_flux_record(cascade), scene.emitter_count});
    vkCmdDispatch(cmd, vkx::group_count(scene.emitter_count, gpu::LPV_EMITTER_GROUP), 1, 1);
  }
  vkx::compute_barrier(cmd);
  vkx::DescriptorWriter(resolve_.descriptor_set())
      .buffer(0, uniform, params.handle())
      .texel_buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, volumes.injected.view())
      .buffer(2, storage, volumes.grids.buffer().handle())
      .buffer(3, storage, volumes.accumulated[0].buffer().handle())
      .buffer(4, storage, volumes.accumulated[1].buffer().handle())
      .buffer(5, storage, volumes.accumulated[2].buffer().handle())
      .buffer(6, storage, volumes.flux_stats.handle())
      .apply(device_.handle());
  resolve_.bind(cmd);
  resolve_.push(cmd, CascadeConstants{cascade, volumes.grid_flux_record(cascade, 0)});
  const glm::uvec3 d = volumes.dims;
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), vkx::group_count(d.z, gpu::LPV_GROUP));
  vkx::compute_barrier(cmd);
}

}  // namespace renderer
