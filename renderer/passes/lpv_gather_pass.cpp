#include "renderer/passes/lpv_gather_pass.hpp"

#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_gather_interface.h"
#include "shaders/lpv_gather.comp.h"
#include "shaders/lpv_gather_bounce.comp.h"
#include "shaders/lpv_gather_sources.comp.h"
#include "shaders/lpv_gather_tail.comp.h"

#include <algorithm>
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
                                 {gpu::GATHER_FACE_COVERS, kTexels},
                                 {gpu::GATHER_ACCUMULATED_STORE_R, kStorage},
                                 {gpu::GATHER_ACCUMULATED_STORE_G, kStorage},
                                 {gpu::GATHER_ACCUMULATED_STORE_B, kStorage},
                                 {gpu::GATHER_SOURCES, kTexels},
                                 {gpu::GATHER_BOUNCE_STORE_R, kStorage},
                                 {gpu::GATHER_BOUNCE_STORE_G, kStorage},
                                 {gpu::GATHER_BOUNCE_STORE_B, kStorage}},
                                sizeof(gpu::LpvGatherPush));
  bounce_layout_ = vkx::compute_layout({{gpu::GATHER_BOUNCE_LPV, kUniform},
                                        {gpu::GATHER_BOUNCE_BLOCKERS, kStorage},
                                        {gpu::GATHER_BOUNCE_LIGHT_R, kTexels},
                                        {gpu::GATHER_BOUNCE_LIGHT_G, kTexels},
                                        {gpu::GATHER_BOUNCE_LIGHT_B, kTexels},
                                        {gpu::GATHER_BOUNCE_INJECTED, kStorage},
                                        {gpu::GATHER_BOUNCE_FLUX_STATS, kStorage},
                                        {gpu::GATHER_BOUNCE_WALLS, kTexels}},
                                       sizeof(gpu::LpvGatherBouncePush));
  tail_ = vkx::Pipeline(device,
                        vkx::compute_layout({{gpu::GATHER_TAIL_LPV, kUniform},
                                             {gpu::GATHER_TAIL_FLUX_STATS, kStorage},
                                             {gpu::GATHER_TAIL_LIGHT_R, kTexels},
                                             {gpu::GATHER_TAIL_LIGHT_G, kTexels},
                                             {gpu::GATHER_TAIL_LIGHT_B, kTexels},
                                             {gpu::GATHER_TAIL_ACCUMULATED_R, kStorage},
                                             {gpu::GATHER_TAIL_ACCUMULATED_G, kStorage},
                                             {gpu::GATHER_TAIL_ACCUMULATED_B, kStorage}},
                                            sizeof(gpu::LpvGatherTailPush)),
                        spirv_lpv_gather_tail_comp);
}

std::uint32_t LpvGatherPass::slabs(const LpvVolumes& volumes) {
  return vkx::group_count(volumes.dims.z, gpu::LPV_GROUP);
}

const vkx::Pipeline& LpvGatherPass::variant(const GatherLines& lines, const vkx::Buffer& params,
                                            const LpvVolumes& volumes) const {
  const std::uint32_t occluded = lines.occlusion ? 1u : 0u;
  const std::uint32_t shared = lines.far_lines == api::FarLines::per_block ? 1u : 0u;
  const std::uint32_t paired = lines.blocking != api::LineBlocking::multiplied ? 1u : 0u;
  const vkx::Pipeline& p = variants_.get(occluded | shared << 1 | paired << 2, [&] {
    // By constant_id: OCCLUDED (0), SHARED_FAR_LINES (1), PAIRED_FACES (2).
    const std::array<std::uint32_t, 3> constants{occluded, shared, paired};
    return vkx::Pipeline(device_, layout_, spirv_lpv_gather_comp, constants);
  });
  vkx::DescriptorWriter(p.descriptor_set())
      .buffer(gpu::GATHER_LPV, kUniform, params.handle())
      .texel_buffer(gpu::GATHER_INJECTED, kTexels, volumes.injected.view())
      .texel_buffer(gpu::GATHER_FACES, kTexels, volumes.faces.view())
      .texel_buffer(gpu::GATHER_FACE_COVERS, kTexels, volumes.face_cover.view())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_R, kStorage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_G, kStorage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::GATHER_ACCUMULATED_STORE_B, kStorage, volumes.accumulated[2].buffer().handle())
      .texel_buffer(gpu::GATHER_SOURCES, kTexels, volumes.grids.view())
      .buffer(gpu::GATHER_BOUNCE_STORE_R, kStorage, volumes.bounce_light[0].buffer().handle())
      .buffer(gpu::GATHER_BOUNCE_STORE_G, kStorage, volumes.bounce_light[1].buffer().handle())
      .buffer(gpu::GATHER_BOUNCE_STORE_B, kStorage, volumes.bounce_light[2].buffer().handle())
      .apply(device_.handle());
  return p;
}

const vkx::Pipeline& LpvGatherPass::reflection(const GatherBounces& bounces, bool splat, const vkx::Buffer& params,
                                               const LpvVolumes& volumes) const {
  const bool trilinear = bounces.injection == api::Injection::trilinear;
  const std::uint32_t walls = bounces.located_walls ? 1u : 0u;
  const vkx::Pipeline& p = bounce_variants_.get((trilinear ? 1u : 0u) | (splat ? 2u : 0u) | walls << 2, [&] {
    // By constant_id: TRILINEAR_INJECTION (0) as the first bounce's VPLs; SPLAT (1); 2 to 5
    // unused; the irradiance read one surfel at a time (UNIFORM_BRANCHES, 6) from cubes
    // (IRRADIANCE_CUBE, 7) past the located walls as the shading reads it (LOCATED_WALLS, 8).
    const std::array<std::uint32_t, 9> constants{trilinear ? 1u : 0u, splat ? 1u : 0u, 0u, 0u, 0u, 0u, 0u, 1u, walls};
    return vkx::Pipeline(device_, bounce_layout_, spirv_lpv_gather_bounce_comp, constants);
  });
  vkx::DescriptorWriter(p.descriptor_set())
      .buffer(gpu::GATHER_BOUNCE_LPV, kUniform, params.handle())
      .buffer(gpu::GATHER_BOUNCE_BLOCKERS, kStorage, bounces.surfels->handle())
      .texel_buffer(gpu::GATHER_BOUNCE_LIGHT_R, kTexels, volumes.bounce_light[0].view())
      .texel_buffer(gpu::GATHER_BOUNCE_LIGHT_G, kTexels, volumes.bounce_light[1].view())
      .texel_buffer(gpu::GATHER_BOUNCE_LIGHT_B, kTexels, volumes.bounce_light[2].view())
      .buffer(gpu::GATHER_BOUNCE_INJECTED, kStorage, volumes.injected.buffer().handle())
      .buffer(gpu::GATHER_BOUNCE_FLUX_STATS, kStorage, volumes.flux_stats.handle())
      .texel_buffer(gpu::GATHER_BOUNCE_WALLS, kTexels, volumes.walls.view())
      .apply(device_.handle());
  return p;
}

void LpvGatherPass::write_tail(const vkx::Buffer& params, const LpvVolumes& volumes) const {
  vkx::DescriptorWriter(tail_.descriptor_set())
      .buffer(gpu::GATHER_TAIL_LPV, kUniform, params.handle())
      .buffer(gpu::GATHER_TAIL_FLUX_STATS, kStorage, volumes.flux_stats.handle())
      .texel_buffer(gpu::GATHER_TAIL_LIGHT_R, kTexels, volumes.bounce_light[0].view())
      .texel_buffer(gpu::GATHER_TAIL_LIGHT_G, kTexels, volumes.bounce_light[1].view())
      .texel_buffer(gpu::GATHER_TAIL_LIGHT_B, kTexels, volumes.bounce_light[2].view())
      .buffer(gpu::GATHER_TAIL_ACCUMULATED_R, kStorage, volumes.accumulated[0].buffer().handle())
      .buffer(gpu::GATHER_TAIL_ACCUMULATED_G, kStorage, volumes.accumulated[1].buffer().handle())
      .buffer(gpu::GATHER_TAIL_ACCUMULATED_B, kStorage, volumes.accumulated[2].buffer().handle())
      .apply(device_.handle());
}

void LpvGatherPass::record_reflection(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t bounce,
                                      const GatherBounces& bounces, const vkx::Pipeline* reflect,
                                      const LpvVolumes& volumes) const {
  // The injected sums, which the last gather read, are replaced.
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(cmd, volumes.injected.buffer().handle(), 0, VK_WHOLE_SIZE, 0);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  if (!reflect) return;  // no surfels: nothing reflects, the next bounce is dark
  reflect->bind(cmd);
  reflect->push(cmd, gpu::LpvGatherBouncePush{cascade, bounces.surfel_count, volumes.bounce_flux_record(cascade, bounce + 1)});
  vkCmdDispatch(cmd, vkx::group_count(bounces.surfel_count, gpu::LPV_BLOCKER_GROUP), 1, 1);
  vkx::compute_barrier(cmd);
}

void LpvGatherPass::record_tail(VkCommandBuffer cmd, std::uint32_t cascade, const GatherBounces& bounces,
                                const vkx::Pipeline& measure, const LpvVolumes& volumes) const {
  const std::uint32_t last = bounces.run.gathered;
  measure.bind(cmd);
  measure.push(cmd, gpu::LpvGatherBouncePush{cascade, bounces.surfel_count, volumes.bounce_flux_record(cascade, last + 1)});
  vkCmdDispatch(cmd, vkx::group_count(bounces.surfel_count, gpu::LPV_BLOCKER_GROUP), 1, 1);
  vkx::compute_barrier(cmd);
  tail_.bind(cmd);
  tail_.push(cmd, gpu::LpvGatherTailPush{cascade, volumes.bounce_flux_record(cascade, last),
                                         volumes.bounce_flux_record(cascade, last + 1)});
  const glm::uvec3 d = volumes.dims;
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP),
                vkx::group_count(d.z, gpu::LPV_GROUP));
  vkx::compute_barrier(cmd);
}

void LpvGatherPass::record(VkCommandBuffer cmd, std::uint32_t cascade, std::uint32_t first, std::uint32_t count,
                           const GatherLines& lines, const GatherBounces& bounces,
                           const vkx::Buffer& params, const LpvVolumes& volumes) const {
  // Every descriptor set is written before the first command: a set updated after it was
  // bound would invalidate the command buffer.
  vkx::DescriptorWriter(sources_.descriptor_set())
      .buffer(gpu::GATHER_SOURCES_LPV, kUniform, params.handle())
      .texel_buffer(gpu::GATHER_SOURCES_INJECTED, kTexels, volumes.injected.view())
      .buffer(gpu::GATHER_SOURCES_STORE, kStorage, volumes.grids.buffer().handle())
      .apply(device_.handle());
  const vkx::Pipeline& gather = variant(lines, params, volumes);
  const bool reflects = bounces.surfel_count > 0;  // else every later bounce is dark
  const vkx::Pipeline* reflect = reflects && bounces.run.gathered > 1 ? &reflection(bounces, true, params, volumes) : nullptr;
  const vkx::Pipeline* measure = reflects && bounces.run.tail ? &reflection(bounces, false, params, volumes) : nullptr;
  if (measure) write_tail(params, volumes);

  const std::uint32_t per_bounce = slabs(volumes);
  const glm::uvec3 d = volumes.dims;
  for (std::uint32_t step = first; step < first + count;) {
    const std::uint32_t bounce = step / per_bounce, slab = step % per_bounce;
    const std::uint32_t run = std::min(first + count - step, per_bounce - slab);  // slabs of this bounce
    if (slab == 0) {  // the sources, once a cascade and bounce
      sources_.bind(cmd);
      sources_.push(cmd, gpu::LpvGatherPush{cascade, 0, 0, 0, 0});
      vkCmdDispatch(cmd, 1, 1, 1);
      vkx::compute_barrier(cmd);
    }
    gather.bind(cmd);
    const bool last = bounce + 1 == bounces.run.gathered;
    const std::uint32_t keep = !last || bounces.run.tail ? 1u : 0u;
    gather.push(cmd, gpu::LpvGatherPush{cascade, slab * gpu::LPV_GROUP, run * gpu::LPV_GROUP, bounce, keep});
    vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), run);
    vkx::compute_barrier(cmd);
    step += run;
    if (slab + run < per_bounce) continue;
    // The bounce is done: the surfels reflect its light as the next bounce's VPLs (their flux
    // known when this submission ends: the executor may stop there), or the bounces after the
    // last are estimated.
    if (!last) record_reflection(cmd, cascade, bounce + 1, bounces, reflect, volumes);
    if (last && measure) record_tail(cmd, cascade, bounces, *measure, volumes);
  }
}

}  // namespace renderer
