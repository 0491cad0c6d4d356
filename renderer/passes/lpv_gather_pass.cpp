#include "renderer/passes/lpv_gather_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_gather_interface.h"
#include "shaders/lpv_gather.comp.h"

#include <array>

namespace renderer {

LpvGatherPass::LpvGatherPass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  layout_ = vkx::compute_layout({{gpu::GATHER_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {gpu::GATHER_INJECTED, texels},
                                 {gpu::GATHER_FACES, texels},
                                 {gpu::GATHER_ACCUMULATED_STORE_R, storage},
                                 {gpu::GATHER_ACCUMULATED_STORE_G, storage},
                                 {gpu::GATHER_ACCUMULATED_STORE_B, storage}},
                                sizeof(gpu::LpvGatherPush));
}

std::uint32_t LpvGatherPass::slabs(const LpvVolumes& volumes) {
  return vkx::group_count(volumes.dims.z, gpu::LPV_GROUP);
}

const vkx::Pipeline& LpvGatherPass::variant(bool occlusion, const vkx::Buffer& params, const LpvVolumes& volumes) const {
  const vkx::Pipeline& p = variants_.get(occlusion ? 1u : 0u, [&] {
    const std::array<std::uint32_t, 1> constants{occlusion ? 1u : 0u};
    return vkx::Pipeline(device_, layout_, spirv_lpv_gather_comp, constants);
  });
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  vkx::DescriptorWriter(p.descriptor_set())
      .buffer(gpu::GATHER_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params.handle())
      .texel_buffer(gpu::GATHER_INJECTED, texels, volumes.injected.view())
      .texel_buffer(gpu::GATHER_FACES, texels, volumes.faces.view())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_R, storage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_G, storage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_B, storage, volumes.accumulated[2].buffer().handle())
      .apply(device_.handle());
  return p;
}

void LpvGatherPass::record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count,
                           bool occlusion, const vkx::Buffer& params, const LpvVolumes& volumes) const {
  const vkx::Pipeline& pipeline = variant(occlusion, params, volumes);
  pipeline.bind(cmd);
  const glm::uvec3 d = volumes.dims;
  pipeline.push(cmd, gpu::LpvGatherPush{cascade, first * gpu::LPV_GROUP, count * gpu::LPV_GROUP});
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), count);
  vkx::compute_barrier(cmd);
}

}  // namespace renderer
