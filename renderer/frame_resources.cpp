#include "renderer/frame_resources.hpp"

#include "api/counted.hpp"
#include "api/request_error.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/passes/geometry_volume_pass.hpp"

#include <algorithm>
#include <string>

namespace renderer {
namespace {

std::string mib(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

void ensure_capacity(const vkx::Device& device, vkx::Buffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage) {
  bytes = std::max<VkDeviceSize>(bytes, 256);  // never zero-sized, even with no lights
  if (!buffer || buffer.size() < bytes) buffer = vkx::Buffer(device, bytes, usage, vkx::MemoryUse::upload);
}

}  // namespace

void FrameResources::fit(const vkx::Device& device, const FramePlan& plan, const api::RenderRequest& request,
                         const LightSetup& lights) {
  const api::Output& out = request.output;
  const std::uint32_t shadow_layers = std::max<std::uint32_t>(1, std::uint32_t(lights.shadow_views.size()));
  const std::uint32_t shadow_res = plan.run[kShadow] ? request.shadows.resolution.value() : 1;
  const std::uint64_t atlas_bytes = std::uint64_t(shadow_res) * shadow_res * shadow_layers * 4;
  if (atlas_bytes > kShadowAtlasBudgetBytes)
    throw api::DoesNotFit("shadows.resolution", api::counted(shadow_layers, "shadow map") + " of " +
                                                      std::to_string(shadow_res) + "^2 need " + mib(atlas_bytes) +
                                                      ", over the budget of " + mib(kShadowAtlasBudgetBytes) +
                                                      ": lower the resolution");
  const bool lpv = plan.run[kInject];
  // Without a light to draw them the RSMs are not read, but the passes still bind a set.
  const std::uint32_t rsm_layers = std::max<std::uint32_t>(1, std::uint32_t(lights.views.size()));
  const std::uint64_t rsm_bytes =
      std::uint64_t(request.lpv.rsm_resolution) * request.lpv.rsm_resolution * rsm_layers * RsmMaps::kBytesPerTexel;
  if (lpv && rsm_bytes > kRsmBudgetBytes)
    throw api::DoesNotFit("lpv.rsm", api::counted(rsm_layers, "reflective shadow map") + " of " +
                                           std::to_string(request.lpv.rsm_resolution) + "^2 need " + mib(rsm_bytes) +
                                           ", over the budget of " + mib(kRsmBudgetBytes) + ": lower the resolution");
  const std::string cells = std::to_string(request.lpv.grid.x) + "x" + std::to_string(request.lpv.grid.y) + "x" +
                            std::to_string(request.lpv.grid.z) + " cells";
  const std::uint32_t geometry_slots = geometry_sources(request.lpv).slots();
  const std::uint32_t accumulated_texels = accumulated_texels_per_cell(request.lpv.transfer);
  const std::uint64_t lpv_bytes =
      LpvVolumes::bytes(request.lpv.grid, request.lpv.cascades, geometry_slots, accumulated_texels);
  if (lpv && lpv_bytes > kLpvBudgetBytes)
    throw api::DoesNotFit("lpv.grid", api::counted(request.lpv.cascades, "cascade") + " of " + cells + " need " +
                                            mib(lpv_bytes) + ", over the budget of " + mib(kLpvBudgetBytes) +
                                            ": use fewer cells");
  const std::uint64_t buffer_bytes =
      LpvVolumes::largest_buffer_bytes(request.lpv.grid, request.lpv.cascades, geometry_slots, accumulated_texels);
  const std::uint64_t buffer_range = device.info().limits.maxStorageBufferRange;
  if (lpv && buffer_bytes > buffer_range)
    throw api::DoesNotFit("lpv.grid", cells + " need a storage buffer of " + mib(buffer_bytes) +
                                            "; this device binds at most " + mib(buffer_range) + ": use fewer cells");
  const std::uint64_t texels = buffer_bytes / vkx::TexelBuffer::kTexelBytes;
  const std::uint64_t texel_limit = device.info().limits.maxTexelBufferElements;
  if (lpv && texels > texel_limit)
    throw api::DoesNotFit("lpv.grid", cells + " need a texel buffer of " + std::to_string(texels) +
                                            " texels; this device binds at most " + std::to_string(texel_limit) +
                                            ": use fewer cells");
  if (!targets || targets->width != out.width || targets->height != out.height) {
    targets.reset();
    targets.emplace(device, out.width, out.height, surfel_stride(out.height));
  }
  if (!atlas || atlas->resolution != shadow_res || atlas->layers != shadow_layers) {
    atlas.reset();
    atlas.emplace(device, shadow_res, shadow_layers);
  }
  if (!lpv) {
    if (!volumes) volumes.emplace(device, glm::uvec3(1), 1, 1, 1);  // something for the shading to bind
    return;  // RSMs and grids of earlier requests stay for the next that needs them
  }
  if (!rsm_maps || rsm_maps->resolution != request.lpv.rsm_resolution || rsm_maps->layers != rsm_layers) {
    rsm_maps.reset();
    rsm_maps.emplace(device, request.lpv.rsm_resolution, rsm_layers);
  }
  if (!volumes || volumes->dims != request.lpv.grid || volumes->cascades != request.lpv.cascades ||
      volumes->geometry_slots < geometry_slots || volumes->accumulated_texels != accumulated_texels) {
    volumes.reset();
    volumes.emplace(device, request.lpv.grid, request.lpv.cascades, geometry_slots, accumulated_texels);
  }
  volumes->set_iterations(device, request.lpv.iterations);
}

void FrameResources::upload(const vkx::Device& device, const gpu::GpuFrame& frame, const LightSetup& lights,
                            const LpvSetup& lpv) {
  const auto light_bytes = lights.lights.size() * sizeof(gpu::GpuLight);
  std::vector<gpu::GpuShadowView> shadow_views;
  for (const glm::mat4& view_proj : lights.shadow_views)  // the inverse in double: perspective maps' near planes are close
    shadow_views.push_back({view_proj, glm::mat4(glm::transpose(glm::inverse(glm::dmat4(view_proj))))});
  const auto view_bytes = shadow_views.size() * sizeof(gpu::GpuShadowView);
  const auto rsm_view_bytes = lpv.rsm_views.size() * sizeof(gpu::GpuRsmView);
  ensure_capacity(device, frame_uniforms, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  // Uniform buffers of the forward and RSM passes too, sized for the most a frame may have.
  const VkBufferUsageFlags both = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  ensure_capacity(device, light_buffer, std::max(light_bytes, gpu::SHADE_MAX_LIGHTS * sizeof(gpu::GpuLight)), both);
  ensure_capacity(device, shadow_view_buffer, std::max(view_bytes, gpu::SHADE_MAX_SHADOW_VIEWS * sizeof(gpu::GpuShadowView)), both);
  ensure_capacity(device, lpv_uniforms, sizeof(lpv.gpu), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  ensure_capacity(device, rsm_view_buffer, std::max(rsm_view_bytes, gpu::SHADE_MAX_SHADOW_VIEWS * sizeof(gpu::GpuRsmView)),
                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  frame_uniforms.write(&frame, sizeof(frame));
  lpv_uniforms.write(&lpv.gpu, sizeof(lpv.gpu));  // read only by frames with indirect light
  if (light_bytes) light_buffer.write(lights.lights.data(), light_bytes);
  if (view_bytes) shadow_view_buffer.write(shadow_views.data(), view_bytes);
  if (rsm_view_bytes) rsm_view_buffer.write(lpv.rsm_views.data(), rsm_view_bytes);
}

}  // namespace renderer
