#include "renderer/passes/geometry_volume_pass.hpp"

#include "api/counted.hpp"
#include "renderer/gpu_types.hpp"
#include "shaders/shared/geometry_volume_interface.h"
#include "shaders/lpv_geometry_corners.comp.h"
#include "shaders/lpv_geometry_inject.comp.h"
#include "shaders/lpv_geometry_resolve.comp.h"

#include <array>
#include <vector>

namespace renderer {

GeometrySources geometry_sources(const api::Lpv& lpv, bool rsm_drawn) {
  GeometrySources s;
  s.rsm = lpv.occlusion_from_rsm && rsm_drawn;
  s.camera = lpv.occlusion_from_camera;
  s.scene = lpv.occlusion_from_scene;
  s.injection = lpv.injection;
  return s;
}

std::string describe_occluders(const GeometrySources& sources, std::uint32_t blockers) {
  std::vector<std::string> parts;
  if (sources.scene) parts.push_back("the scene's surfaces (" + api::counted(blockers, "piece") + ")");
  if (sources.rsm) parts.push_back("the RSMs' surfels");
  if (sources.camera) parts.push_back("the camera's surfels");
  std::string text = "occluders:";
  for (std::size_t i = 0; i < parts.size(); ++i)
    text += (i == 0 ? " " : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return text;
}

GeometryVolumePass::GeometryVolumePass(const vkx::Device& device) : device_(device) {
  const VkDescriptorType uniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  const VkDescriptorType buffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
  inject_layout_ = vkx::compute_layout({{gpu::GEOMETRY_INJECT_LPV, uniform},
                                        {gpu::GEOMETRY_INJECT_RSM_POSITION, image},
                                        {gpu::GEOMETRY_INJECT_RSM_NORMAL, image},
                                        {gpu::GEOMETRY_INJECT_RSM_FLUX, image},
                                        {gpu::GEOMETRY_INJECT_CAMERA_POSITION, image},
                                        {gpu::GEOMETRY_INJECT_CAMERA_NORMAL, image},
                                        {gpu::GEOMETRY_INJECT_CAMERA_ALBEDO, image},
                                        {gpu::GEOMETRY_INJECT_CORNER_SUMS, buffer},
                                        {gpu::GEOMETRY_INJECT_BLOCKERS, buffer}},
                                       sizeof(gpu::GeometryInjectPush));
  corners_layout_ = vkx::compute_layout({{gpu::GEOMETRY_CORNERS_LPV, uniform},
                                         {gpu::GEOMETRY_CORNERS_SUMS, texels},
                                         {gpu::GEOMETRY_CORNERS_CORNERS, buffer}},
                                        sizeof(gpu::GeometryCornersPush));
  resolve_layout_ = vkx::compute_layout({{gpu::GEOMETRY_RESOLVE_LPV, uniform},
                                         {gpu::GEOMETRY_RESOLVE_CORNERS, texels},
                                         {gpu::GEOMETRY_RESOLVE_FACES, buffer},
                                         {gpu::GEOMETRY_RESOLVE_FACE_ALBEDO, buffer},
                                         {gpu::GEOMETRY_RESOLVE_FACE_COVER, buffer},
                                         {gpu::GEOMETRY_RESOLVE_WALLS, buffer}},
                                        sizeof(gpu::GeometryResolvePush));
}

void GeometryVolumePass::record(VkCommandBuffer cmd, std::uint32_t cascade, const vkx::Buffer& params,
                                const RsmMaps& maps, const std::vector<gpu::GpuRsmView>& rsm_views,
                                const GBuffer& camera, const GpuScene& scene, const GeometrySources& sources,
                                const LpvVolumes& volumes) const {
  const VkDescriptorType image = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  const VkImageLayout general = VK_IMAGE_LAYOUT_GENERAL;
  const std::uint32_t trilinear = sources.injection == api::Injection::trilinear ? 1u : 0u;
  const std::array<std::uint32_t, 1> with_albedo{sources.bounces ? 1u : 0u};
  const vkx::Pipeline& inject = inject_.get(2 * with_albedo[0] + trilinear, [&] {
    return vkx::Pipeline(device_, inject_layout_, spirv_lpv_geometry_inject_comp,
                         std::array<std::uint32_t, 2>{trilinear, with_albedo[0]});
  });
  vkx::DescriptorWriter(inject.descriptor_set())
      .buffer(gpu::GEOMETRY_INJECT_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params.handle())
      .image(gpu::GEOMETRY_INJECT_RSM_POSITION, image, maps.position.view(), general)
      .image(gpu::GEOMETRY_INJECT_RSM_NORMAL, image, maps.normal.view(), general)
      .image(gpu::GEOMETRY_INJECT_RSM_FLUX, image, maps.flux.view(), general)
      .image(gpu::GEOMETRY_INJECT_CAMERA_POSITION, image, camera.position.view(), general)
      .image(gpu::GEOMETRY_INJECT_CAMERA_NORMAL, image, camera.normal.view(), general)
      .image(gpu::GEOMETRY_INJECT_CAMERA_ALBEDO, image, camera.albedo.view(), general)
      .buffer(gpu::GEOMETRY_INJECT_CORNER_SUMS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.corner_sums.buffer().handle())
      .buffer(gpu::GEOMETRY_INJECT_BLOCKERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene.blockers.handle())
      .apply(device_.handle());
  const vkx::Pipeline& corners = corners_.get(with_albedo[0], [&] {
    return vkx::Pipeline(device_, corners_layout_, spirv_lpv_geometry_corners_comp, with_albedo);
  });
  const std::array<std::uint32_t, 3> resolved{with_albedo[0], sources.covers ? 1u : 0u,
                                              sources.walls ? 1u : 0u};  // BOUNCES, COVERS, WALLS
  const vkx::Pipeline& resolve = resolve_.get(resolved[0] | resolved[1] << 1 | resolved[2] << 2, [&] {
    return vkx::Pipeline(device_, resolve_layout_, spirv_lpv_geometry_resolve_comp, resolved);
  });
  vkx::DescriptorWriter(corners.descriptor_set())
      .buffer(gpu::GEOMETRY_CORNERS_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params.handle())
      .texel_buffer(gpu::GEOMETRY_CORNERS_SUMS, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, volumes.corner_sums.view())
      .buffer(gpu::GEOMETRY_CORNERS_CORNERS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.corners.buffer().handle())
      .apply(device_.handle());
  vkx::DescriptorWriter(resolve.descriptor_set())
      .buffer(gpu::GEOMETRY_RESOLVE_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, params.handle())
      .texel_buffer(gpu::GEOMETRY_RESOLVE_CORNERS, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, volumes.corners.view())
      .buffer(gpu::GEOMETRY_RESOLVE_FACES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.faces.buffer().handle())
      .buffer(gpu::GEOMETRY_RESOLVE_FACE_ALBEDO, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.face_albedo.buffer().handle())
      .buffer(gpu::GEOMETRY_RESOLVE_FACE_COVER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.face_cover.buffer().handle())
      .buffer(gpu::GEOMETRY_RESOLVE_WALLS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, volumes.walls.buffer().handle())
      .apply(device_.handle());

  const std::uint32_t slots = sources.slots();
  vkCmdFillBuffer(cmd, volumes.corner_sums.buffer().handle(), 0, volumes.corner_sum_bytes(slots, sources.bounces), 0);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  inject.bind(cmd);
  if (sources.rsm) {
    for (std::uint32_t layer = 0; layer < maps.layers && layer < rsm_views.size(); ++layer) {
      const std::uint32_t texels = std::min(rsm_views[layer].info.z, maps.resolution), stride = rsm_views[layer].info.w;
      inject.push(cmd, gpu::GeometryInjectPush{cascade, gpu::LPV_GV_SOURCE_RSM, sources.slot(gpu::LPV_GV_SOURCE_RSM), slots,
                                               0, layer, texels, stride});
      const std::uint32_t side = vkx::group_count(texels, stride);
      vkCmdDispatch(cmd, vkx::group_count(side, gpu::LPV_VPL_GROUP), vkx::group_count(side, gpu::LPV_VPL_GROUP), 1);
    }
  }
  if (sources.camera) {
    inject.push(cmd, gpu::GeometryInjectPush{cascade, gpu::LPV_GV_SOURCE_CAMERA,
                                             sources.slot(gpu::LPV_GV_SOURCE_CAMERA), slots, 0, 0, 0, 0});
    vkCmdDispatch(cmd, vkx::group_count(camera.width, gpu::LPV_VPL_GROUP),
                  vkx::group_count(camera.height, gpu::LPV_VPL_GROUP), 1);
  }
  if (sources.scene && scene.blocker_count) {
    inject.push(cmd, gpu::GeometryInjectPush{cascade, gpu::LPV_GV_SOURCE_SCENE,
                                             sources.slot(gpu::LPV_GV_SOURCE_SCENE), slots, scene.blocker_count, 0, 0, 0});
    vkCmdDispatch(cmd, vkx::group_count(scene.blocker_count, gpu::LPV_BLOCKER_GROUP), 1, 1);
  }
  vkx::compute_barrier(cmd);
  const glm::uvec3 d = volumes.dims;
  corners.bind(cmd);
  corners.push(cmd, gpu::GeometryCornersPush{cascade, slots});
  vkCmdDispatch(cmd, vkx::group_count(d.x + 1, gpu::LPV_GROUP), vkx::group_count(d.y + 1, gpu::LPV_GROUP), vkx::group_count(d.z + 1, gpu::LPV_GROUP));
  vkx::compute_barrier(cmd);
  resolve.bind(cmd);
  resolve.push(cmd, gpu::GeometryResolvePush{cascade});
  vkCmdDispatch(cmd, vkx::group_count(d.x, gpu::LPV_GROUP), vkx::group_count(d.y, gpu::LPV_GROUP), vkx::group_count(d.z, gpu::LPV_GROUP));
  vkx::compute_barrier(cmd);
}

}  // namespace renderer
