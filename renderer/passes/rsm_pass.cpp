#include "renderer/passes/rsm_pass.hpp"

#include "shaders/rsm.frag.h"
#include "shaders/rsm.vert.h"
#include "shaders/shared/rsm_interface.h"
#include "vkx/rendering.hpp"

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace renderer {
namespace {

// The push constants of rsm.vert and rsm.frag: the draw's material, then the view (layer).
struct DrawConstants {
  gpu::GpuDrawMaterial material;
  std::uint32_t view;
};
static_assert(offsetof(DrawConstants, view) == sizeof(gpu::GpuDrawMaterial), "as std430 lays out the push constants");

vkx::PipelineLayoutDesc rsm_layout(const TextureSetLayout& textures) {
  const VkShaderStageFlags vs_fs = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  vkx::PipelineLayoutDesc layout;
  layout.bindings = {vkx::binding(gpu::RSM_VIEWS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vs_fs),
                     vkx::binding(gpu::RSM_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
  layout.draw_sets = {textures.handle()};
  layout.push_constant_bytes = sizeof(DrawConstants);
  layout.push_constant_stages = vs_fs;
  return layout;
}

vkx::GraphicsPipelineDesc rsm_pipeline(MaterialVariant variant) {
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_rsm_vert;
  g.fragment_spirv = spirv_rsm_frag;
  g.fragment_specialization = {variant.textured};
  g.vertex_input = scene_vertex_input();
  g.color_formats = {RsmMaps::kPositionFormat, RsmMaps::kNormalFormat, RsmMaps::kFluxFormat};
  g.depth_format = RsmMaps::kDepthFormat;
  g.cull_mode = VK_CULL_MODE_NONE;  // the first surface the light meets, whichever way it faces
  return g;
}

// The RSM draws both sides of every surface; only texturing selects its pipeline.
MaterialVariant rsm_variant(MaterialVariant v) { return {false, v.textured}; }

}  // namespace

RsmPass::RsmPass(const vkx::Device& device, const TextureSetLayout& textures)
    : device_(device), pipelines_(device, rsm_layout(textures), rsm_pipeline) {
  // The forward pass reads every shadow view of a frame from one uniform buffer, this pass
  // every RSM view (as many: six a light at most).
  const VkDeviceSize uniform_range = gpu::SHADE_MAX_SHADOW_VIEWS * sizeof(gpu::GpuRsmView);
  static_assert(sizeof(gpu::GpuRsmView) >= sizeof(gpu::mat4), "the RSM views' buffer is the larger");
  const vkx::DeviceInfo& info = device.info();
  if (info.limits.maxUniformBufferRange < uniform_range)
    throw std::runtime_error("device '" + info.name + "' binds uniform buffers of at most " +
                             std::to_string(info.limits.maxUniformBufferRange) + " bytes; the RSM pass needs " +
                             std::to_string(uniform_range));
  pipelines_.get({});
}

void RsmPass::record(VkCommandBuffer cmd, const GpuScene& scene, const RsmMaps& maps, const vkx::Buffer& views,
                     const std::vector<gpu::GpuRsmView>& view_info, const vkx::Buffer& lights) const {
  for (MaterialVariant variant : scene.variants_in_use)  // before any is bound
    vkx::DescriptorWriter(pipelines_.get(rsm_variant(variant)).descriptor_set())
        .buffer(gpu::RSM_VIEWS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, views.handle())
        .buffer(gpu::RSM_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, lights.handle())
        .apply(device_.handle());
  const std::array<const vkx::Image*, 3> colors{&maps.position, &maps.normal, &maps.flux};
  vkx::prepare_attachments(cmd, colors, &maps.depth);
  for (std::uint32_t layer = 0; layer < maps.layers; ++layer) {
    const std::array<VkImageView, 3> views{maps.position.layer_view(layer), maps.normal.layer_view(layer),
                                           maps.flux.layer_view(layer)};
    // The readers stay within the view's resolution: the rest of the layer is neither cleared
    // nor drawn.
    const std::uint32_t side = std::min(view_info.at(layer).info.z, maps.resolution);
    vkx::begin_cleared_rendering(device_, cmd, views, maps.depth.layer_view(layer), {side, side}, false);
    scene.draw_all(
        cmd, [&](MaterialVariant variant) -> const vkx::Pipeline& { return pipelines_.get(rsm_variant(variant)); },
        [&](const scene::Draw& draw) { return DrawConstants{scene.draw_material(draw), layer}; });
    device_.cmd_end_rendering(cmd);
  }
  vkx::colors_to_compute(cmd, colors);
}

void RsmPass::record_skipped(VkCommandBuffer cmd, const RsmMaps& maps) {
  const std::array<const vkx::Image*, 3> colors{&maps.position, &maps.normal, &maps.flux};
  vkx::undrawn_to_compute(cmd, colors);
}

}  // namespace renderer
