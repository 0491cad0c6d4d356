#include "renderer/passes/lpv_propagate_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_propagate_interface.h"
#include "shaders/lpv_propagate.comp.h"

#include <array>

namespace renderer {
namespace {

// The cells an invocation walks along z. On lavapipe each invocation is a SIMD lane of a
// CPU thread, and a long column reuses the cells and the face it read for the next step
// (8 measured best there, docs/lpv.md). A GPU needs invocations instead: columns of 8 give a
// 32^3 grid 4096 of them, a fraction of what one GPU runs at once, and each walks 8 cells of
// dependent loads. On an H100, columns of 2 propagate 32^3 x 8 in 0.075 ms against 0.173,
// 64^3 x 8 in 0.260 against 0.321; 1 is no faster at 32^3 and slower at 64^3
// (lpv-render --propagate-column, docs/lpv.md "On a real GPU").
std::uint32_t device_column_length(const vkx::Device& device) {
  return device.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU ? gpu::LPV_PROPAGATE_COLUMN_CPU
                                                           : gpu::LPV_PROPAGATE_COLUMN_GPU;
}

}  // namespace

LpvPropagatePass::LpvPropagatePass(const vkx::Device& device, std::uint32_t column_length)
    : device_(device), column_length_(column_length ? column_length : device_column_length(device)) {
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  layout_ = vkx::compute_layout({{gpu::PROPAGATE_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                 {gpu::PROPAGATE_GRIDS, texels},
                                 {gpu::PROPAGATE_ACCUMULATED_R, texels},
                                 {gpu::PROPAGATE_ACCUMULATED_G, texels},
                                 {gpu::PROPAGATE_ACCUMULATED_B, texels},
                                 {gpu::PROPAGATE_FACES, texels},
                                 {gpu::PROPAGATE_FLUX_STATS, storage},
                                 {gpu::PROPAGATE_GRID_STORE, storage},
                                 {gpu::PROPAGATE_ACCUMULATED_STORE_R, storage},
                                 {gpu::PROPAGATE_ACCUMULATED_STORE_G, storage},
                                 {gpu::PROPAGATE_ACCUMULATED_STORE_B, storage},
                                 {gpu::PROPAGATE_FACE_ALBEDO, texels}},
                                sizeof(gpu::LpvPropagatePush));
}

const vkx::Pipeline& LpvPropagatePass::variant(Variant v, const vkx::Buffer& params, const LpvVolumes& volumes) const {
  const vkx::Pipeline& p = variants_.get(v, [&] {
    const std::array<std::uint32_t, 3> constants{v != kOpen ? 1u : 0u, v == kOccludedBounces ? 1u : 0u,
                                                 column_length_};
    return vkx::Pipeline(device_, layout_, spirv_lpv_propagate_comp, constants);
  });
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  vkx::DescriptorWriter(p.descriptor_set())
      .buffer(gpu::PROPAGATE_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params.handle())
      .texel_buffer(gpu::PROPAGATE_GRIDS, texels, volumes.grids.view())
      .texel_buffer(gpu::PROPAGATE_ACCUMULATED_R, texels, volumes.accumulated[0].view())
      .texel_buffer(gpu::PROPAGATE_ACCUMULATED_G, texels, volumes.accumulated[1].view())
      .texel_buffer(gpu::PROPAGATE_ACCUMULATED_B, texels, volumes.accumulated[2].view())
      .texel_buffer(gpu::PROPAGATE_FACES, texels, volumes.faces.view())
      .buffer(gpu::PROPAGATE_FLUX_STATS, storage, volumes.flux_stats.handle())
      .buffer(gpu::PROPAGATE_GRID_STORE, storage, volumes.grids.buffer().handle())
      .buffer(gpu::PROPAGATE_ACCUMULATED_STORE_R, storage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::PROPAGATE_ACCUMULATED_STORE_G, storage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::PROPAGATE_ACCUMULATED_STORE_B, storage, volumes.accumulated[2].buffer().handle())
      .texel_buffer(gpu::PROPAGATE_FACE_ALBEDO, texels, volumes.face_albedo.view())
      .apply(device_.handle());
  return p;
}

void LpvPropagatePass::record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count,
                              bool occlusion, bool bounces, const vkx::Buffer& params,
                              const LpvVolumes& volumes) const {
  const Variant v = !occlusion ? kOpen : bounces ? kOccludedBounces : kOccluded;
  const vkx::Pipeline& pipeline = variant(v, params, volumes);
  pipeline.bind(cmd);
  const glm::uvec3 d = volumes.dims;
  for (std::uint32_t k = first; k < first + count; ++k) {
    pipeline.push(cmd, gpu::LpvPropagatePush{cascade, volumes.grid_flux_record(cascade, k), k});
    vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_PROPAGATE_GROUP), vkx::group_count(d.y, gpu::LPV_PROPAGATE_GROUP),
                  vkx::group_count(d.z, column_length_));
    vkx::compute_barrier(cmd);
  }
}

}  // namespace renderer
