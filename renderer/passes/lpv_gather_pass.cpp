#include "renderer/passes/lpv_gather_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_gather_interface.h"
#include "shaders/lpv_gather.comp.h"
#include "shaders/lpv_gather_sources.comp.h"

#include <array>

namespace renderer {

namespace {

const VkDescriptorType kTexels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
const VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
const VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;

}  // namespace

LpvGatherPass::LpvGatherPass(const vkx::Device& device)
    : device_(device),
      sources_(device,
               vkx::compute_layout({{gpu::GATHER_SOURCES_LPV, kUniform},
                                    {gpu::GATHER_SOURCES_INJECTED, kTexels},
                                    {gpu::GATHER_SOURCES_STORE, kStorage}},
                                   sizeof(gpu::LpvGatherPush)),
               spirv_lpv_gather_sources_comp) {
  layout_ = vkx::compute_layout({{gpu::GATHER_LPV, kUniform},
                                 {gpu::GATHER_INJECTED, kTexels},
                                 {gpu::GATHER_FACES, kTexels},
                                 {gpu::GATHER_ACCUMULATED_STORE_R, kStorage},
                                 {gpu::GATHER_ACCUMULATED_STORE_G, kStorage},
                                 {gpu::GATHER_ACCUMULATED_STORE_B, kStorage},
                                 {gpu::GATHER_SOURCES, kTexels}},
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
  vkx::DescriptorWriter(p.descriptor_set())
      .buffer(gpu::GATHER_LPV, kUniform, params.handle())
      .texel_buffer(gpu::GATHER_INJECTED, kTexels, volumes.injected.view())
      .texel_buffer(gpu::GATHER_FACES, kTexels, volumes.faces.view())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_R, kStorage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_G, kStorage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_B, kStorage, volumes.accumulated[2].buffer().handle())
      .texel_buffer(gpu::GATHER_SOURCES, kTexels, volumes.grids.view())
      .apply(device_.handle());
  return p;
}

void LpvGatherPass::record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count,
                           bool occlusion, const vkx::Buffer& params, const LpvVolumes& volumes) const {
  if (first == 0) {  // the sources, once a cascade
    vkx::DescriptorWriter(sources_.descriptor_set())
        .buffer(gpu::GATHER_SOURCES_LPV, kUniform, params.handle())
        .texel_buffer(gpu::GATHER_SOURCES_INJECTED, kTexels, volumes.injected.view())
        .buffer(gpu::GATHER_SOURCES_STORE, kStorage, volumes.grids.buffer().handle())
        .apply(device_.handle());
    sources_.bind(cmd);
    sources_.push(cmd, gpu::LpvGatherPush{cascade, 0, 0});
    vkCmdDispatch(cmd, 1, 1, 1);
    vkx::compute_barrier(cmd);
  }
  const vkx::Pipeline& pipeline = variant(occlusion, params, volumes);
  pipeline.bind(cmd);
  const glm::uvec3 d = volumes.dims;
  pipeline.push(cmd, gpu::LpvGatherPush{cascade, first * gpu::LPV_GROUP, count * gpu::LPV_GROUP});
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), count);
  vkx::compute_barrier(cmd);
}

}  // namespace renderer
