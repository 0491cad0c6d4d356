#include "renderer/lpv/lpv_volumes.hpp"

#include <algorithm>

#include "api/render_request.hpp"
#include "renderer/gpu_types.hpp"
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_gather.h"

#include <glm/vec3.hpp>

namespace renderer {
namespace {

constexpr VkDeviceSize kInjectedBytesPerCell = 12 * 8;
constexpr VkDeviceSize kCornerSumBytesPerSlot = gpu::LPV_GV_WORDS * 8;
constexpr VkDeviceSize kGridTexelsPerCell = 2 * 3;  // two grids of three channels
constexpr VkDeviceSize kAccumulatedBytesPerTexel = 3 * vkx::TexelBuffer::kTexelBytes;  // a texel per channel
constexpr VkDeviceSize kCornerTexels = gpu::LPV_GV_CORNER_TEXELS;
constexpr VkDeviceSize kCornerBytes = kCornerTexels * vkx::TexelBuffer::kTexelBytes;
constexpr VkDeviceSize kFaceTexelsPerCell = 6;  // lpv_grid.glsl: the SH and spread of 3 faces
constexpr VkDeviceSize kFaceBytesPerCell = kFaceTexelsPerCell * vkx::TexelBuffer::kTexelBytes;
constexpr VkDeviceSize kFaceAlbedoTexelsPerCell = 3;
constexpr VkDeviceSize kFaceAlbedoBytesPerCell = kFaceAlbedoTexelsPerCell * vkx::TexelBuffer::kTexelBytes;
constexpr VkDeviceSize kFaceCoverTexelsPerCell = 3;  // lpv_grid.glsl: lpv_face_cover_texel
constexpr VkDeviceSize kFaceCoverBytesPerCell = kFaceCoverTexelsPerCell * vkx::TexelBuffer::kTexelBytes;
constexpr VkDeviceSize kWallBytesPerCell = vkx::TexelBuffer::kTexelBytes;  // per cascade: lpv_accumulated_texel
constexpr VkFormat kSums = VK_FORMAT_R32G32B32A32_UINT;
constexpr std::size_t kRecordInt64s = gpu::LPV_FLUX_SLOTS * gpu::LPV_FLUX_SLOT_INT64S;  // one flux_stats record
constexpr std::uint32_t kBounceRecords = api::limits::max_bounces;  // bounces 2 .. max + 1 (bounce_flux_record)

std::uint64_t cell_count(glm::uvec3 d) { return std::uint64_t(d.x) * d.y * d.z; }

vkx::Image rsm_target(const vkx::Device& device, VkFormat format, std::uint32_t res, std::uint32_t layers) {
  return vkx::Image(device, {format, res, res, layers,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT, true});
}

}  // namespace

RsmMaps::RsmMaps(const vkx::Device& device, std::uint32_t res, std::uint32_t n)
    : resolution(res),
      layers(n),
      position(rsm_target(device, kPositionFormat, res, n)),
      normal(rsm_target(device, kNormalFormat, res, n)),
      flux(rsm_target(device, kFluxFormat, res, n)),
      depth(device, {kDepthFormat, res, res, n, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
                     true}) {}

std::uint64_t LpvVolumes::grid_texels(glm::uvec3 d) {
  const std::uint64_t pyramid = std::uint64_t(gpu::lpv_gather_records(glm::ivec3(d))) * gpu::LPV_GATHER_RECORD_TEXELS;
  return std::max(cell_count(d) * kGridTexelsPerCell, pyramid);
}

std::uint64_t LpvVolumes::bytes(glm::uvec3 dims, std::uint32_t cascades, std::uint32_t geometry_slots,
                                std::uint32_t accumulated_texels) {
  const std::uint64_t cells = cell_count(dims);
  return cells * (kInjectedBytesPerCell + kFaceBytesPerCell + kFaceAlbedoBytesPerCell + kFaceCoverBytesPerCell +
                  kWallBytesPerCell * cascades + 2 * kAccumulatedBytesPerTexel * accumulated_texels * cascades) +
         grid_texels(dims) * vkx::TexelBuffer::kTexelBytes +
         cell_count(dims + 1u) * (kCornerBytes + geometry_slots * kCornerSumBytesPerSlot);
}

std::uint64_t LpvVolumes::largest_buffer_bytes(glm::uvec3 dims, std::uint32_t cascades, std::uint32_t geometry_slots,
                                               std::uint32_t accumulated_texels) {
  const std::uint64_t per_cell = std::max(
      {kInjectedBytesPerCell, kFaceBytesPerCell, accumulated_texels * cascades * vkx::TexelBuffer::kTexelBytes});
  return std::max({cell_count(dims) * per_cell, grid_texels(dims) * vkx::TexelBuffer::kTexelBytes,
                   cell_count(dims + 1u) * geometry_slots * kCornerSumBytesPerSlot});
}

LpvVolumes::LpvVolumes(const vkx::Device& device, glm::uvec3 d, std::uint32_t c, std::uint32_t slots,
                       std::uint32_t texels)
    : dims(d),
      cascades(c),
      geometry_slots(slots),
      accumulated_texels(texels),
      injected(device, cell_count(d) * kInjectedBytesPerCell / vkx::TexelBuffer::kTexelBytes, kSums),
      corner_sums(device, cell_count(d + 1u) * slots * kCornerSumBytesPerSlot / vkx::TexelBuffer::kTexelBytes, kSums),
      grids(device, grid_texels(d)),
      accumulated{vkx::TexelBuffer(device, cell_count(d) * c * texels), vkx::TexelBuffer(device, cell_count(d) * c * texels),
                  vkx::TexelBuffer(device, cell_count(d) * c * texels)},
      bounce_light{vkx::TexelBuffer(device, cell_count(d) * c * texels), vkx::TexelBuffer(device, cell_count(d) * c * texels),
                   vkx::TexelBuffer(device, cell_count(d) * c * texels)},
      corners(device, cell_count(d + 1u) * kCornerTexels),
      faces(device, cell_count(d) * kFaceTexelsPerCell),
      face_albedo(device, cell_count(d) * kFaceAlbedoTexelsPerCell),
      face_cover(device, cell_count(d) * kFaceCoverTexelsPerCell),
      walls(device, cell_count(d) * c, kSums) {
  device.run_once([&](VkCommandBuffer cmd) {
    // The accumulated light of cascades a frame does not propagate, and the faces before a
    // geometry volume was ever built, are read (with zero effect).
    for (const vkx::TexelBuffer* b :
         {&accumulated[0], &accumulated[1], &accumulated[2], &faces, &face_albedo, &face_cover, &walls})
      vkCmdFillBuffer(cmd, b->buffer().handle(), 0, VK_WHOLE_SIZE, 0);
    vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  });
}

VkDeviceSize LpvVolumes::corner_sum_bytes(std::uint32_t slots, bool bounces) const {
  return VkDeviceSize(cell_count(dims + 1u)) * slots * gpu::lpv_gv_corner_words(bounces) * 8;
}

void LpvVolumes::set_iterations(const vkx::Device& device, std::uint32_t n) {
  iterations = n;
  records_per_cascade = n + 2 + kBounceRecords;
  const VkDeviceSize bytes = VkDeviceSize(records_per_cascade) * cascades * kRecordInt64s * 8;
  if (!flux_stats || flux_stats.size() < bytes)
    flux_stats = vkx::Buffer(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             vkx::MemoryUse::readback);
}

glm::dvec3 LpvVolumes::flux_at(std::uint32_t record, double watts_per_unit) const {
  const auto* slot = static_cast<const std::int64_t*>(flux_stats.mapped()) + std::size_t(record) * kRecordInt64s;
  std::int64_t units[3] = {0, 0, 0};
  for (std::uint32_t s = 0; s < gpu::LPV_FLUX_SLOTS; ++s, slot += gpu::LPV_FLUX_SLOT_INT64S)
    for (int c = 0; c < 3; ++c) units[c] += slot[c];
  return glm::dvec3(double(units[0]), double(units[1]), double(units[2])) * watts_per_unit;
}

}  // namespace renderer
