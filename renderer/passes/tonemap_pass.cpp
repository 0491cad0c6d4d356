#include "renderer/passes/tonemap_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/tonemap.comp.h"

namespace renderer {

TonemapPass::TonemapPass(const vkx::Device& device) : device_(device) {
  const vkx::PipelineLayoutDesc layout = vkx::compute_layout(
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, sizeof(gpu::GpuTonemapParams));
  pipeline_ = vkx::Pipeline(device, layout, spirv_tonemap_comp);
}

void TonemapPass::record(VkCommandBuffer cmd, const FrameTargets& targets, api::Tonemap curve,
                         bool display_encode) const {
  vkx::DescriptorWriter(pipeline_.descriptor_set())
      .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, targets.linear.handle())
      .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, targets.display.handle())
      .apply(device_.handle());
  gpu::GpuTonemapParams params{};
  params.size_mode.x = targets.width;
  params.size_mode.y = targets.height;
  switch (curve) {
    case api::Tonemap::none: params.size_mode.z = gpu::TONEMAP_NONE; break;
    case api::Tonemap::reinhard: params.size_mode.z = gpu::TONEMAP_REINHARD; break;
    case api::Tonemap::aces: params.size_mode.z = gpu::TONEMAP_ACES; break;
  }
  params.size_mode.w = display_encode ? 1u : 0u;
  pipeline_.bind(cmd);
  pipeline_.push(cmd, params);
  vkCmdDispatch(cmd, (targets.width + gpu::SHADE_GROUP_X - 1) / gpu::SHADE_GROUP_X,
                (targets.height + gpu::SHADE_GROUP_Y - 1) / gpu::SHADE_GROUP_Y, 1);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace renderer
