#include "renderer/passes/forward_pass.hpp"

#include "renderer/passes/display_encoding.hpp"
#include "shaders/forward.frag.h"
#include "shaders/gbuffer.vert.h"
#include "shaders/shared/camera_raster_interface.h"
#include "vkx/rendering.hpp"

#include <array>

namespace renderer {

static_assert(gpu::SHADE_MAX_LIGHTS == api::limits::max_lights, "the forward pass's light buffer holds every light");

ForwardPass::ForwardPass(const vkx::Device& device, const TextureSetLayout& textures) : device_(device) {
  const VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
  layout_.bindings = {
      vkx::binding(gpu::CAMERA_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT | fragment),
      vkx::binding(gpu::FORWARD_SHADOW_MAPS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment),
      vkx::binding(gpu::FORWARD_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_LPV, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_ACCUMULATED_R, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_ACCUMULATED_G, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_ACCUMULATED_B, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, fragment),
      vkx::binding(gpu::FORWARD_WALLS, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, fragment)};
  layout_.draw_sets = {textures.handle()};
  layout_.push_constant_bytes = sizeof(gpu::GpuDrawMaterial);
  layout_.push_constant_stages = fragment;
  shadow_sampler_ = vkx::Sampler(device, VK_FILTER_NEAREST);  // depths, compared in direct_light.glsl
}

const vkx::Pipeline& ForwardPass::pipeline(MaterialVariant variant, const DirectLightInputs& direct,
                                           const IndirectLightInputs& indirect, std::uint32_t curve) const {
  // Bits 0-1: the material variant; 2-3: the tone curve; 4-6: the cascades (at most 4); 7: the
  // irradiance cube; 8: the located walls; above: the lights (11 bits).
  const std::uint32_t cascades = indirect.cascades;
  const std::uint32_t cube = indirect.cube() ? 1u : 0u;
  const std::uint32_t walls = indirect.located_walls() ? 1u : 0u;
  const std::uint32_t key = (direct_light_key(direct) << 9) | (walls << 8) | (cube << 7) | (cascades << 4) |
                            (curve << 2) | variant.index();
  return pipelines_.get(key, [&] {
    vkx::GraphicsPipelineDesc g;
    g.vertex_spirv = spirv_gbuffer_vert;
    g.fragment_spirv = spirv_forward_frag;
    g.fragment_specialization = {variant.double_sided, variant.textured, direct.light_kinds,
                                 specialised_light_count(direct), curve, cascades, device_.info().uniform_branches,
                                 cube, walls};
    g.vertex_input = scene_vertex_input();
    g.color_formats = {FrameTargets::kDisplayFormat};
    g.depth_format = GBuffer::kDepthFormat;
    // As the G-buffer: counter-clockwise front faces, back faces culled unless double-sided.
    g.cull_mode = variant.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    g.front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    return vkx::Pipeline(device_, layout_, g);
  });
}

void ForwardPass::record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const std::uint32_t> order,
                         const FrameTargets& targets, const DirectLightInputs& direct,
                         const IndirectLightInputs& indirect, api::Tonemap tone_curve) const {
  const std::uint32_t curve = gpu_tone_curve(tone_curve);
  auto pipeline_for = [&](MaterialVariant variant) -> const vkx::Pipeline& {
    return pipeline(variant, direct, indirect, curve);
  };
  for (MaterialVariant variant : scene.variants_in_use) {  // before any is bound
    vkx::DescriptorWriter writer(pipeline_for(variant).descriptor_set());
    bind_indirect_light(writer, gpu::FORWARD_LPV, indirect)
        .buffer(gpu::CAMERA_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, direct.frame.handle())
        .image(gpu::FORWARD_SHADOW_MAPS, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, direct.atlas.depth.view(),
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, shadow_sampler_.handle())
        .buffer(gpu::FORWARD_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, direct.lights.handle())
        .buffer(gpu::FORWARD_SHADOW_VIEWS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, direct.shadow_views.handle())
        .apply(device_.handle());
  }
  const std::array<const vkx::Image*, 1> colors{&targets.display_target};
  vkx::prepare_attachments(cmd, colors, &targets.camera.depth);
  const std::array<VkImageView, 1> views{targets.display_target.view()};
  // Opaque black where nothing is drawn, as the shading encodes a pixel without a surface.
  vkx::begin_cleared_rendering(device_, cmd, views, targets.camera.depth.view(), {targets.width, targets.height}, false,
                               vkx::ClearColors::all, 1.0f);
  scene.draw_all(
      cmd, pipeline_for, [&](const scene::Draw& draw) { return scene.draw_material(draw); }, order);
  device_.cmd_end_rendering(cmd);

  // Into host memory, rows top to bottom as the shading writes the display image.
  const VkImageLayout src = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  vkx::transition(cmd, targets.display_target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, src,
                  VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {targets.width, targets.height, 1};
  vkCmdCopyImageToBuffer(cmd, targets.display_target.handle(), src, targets.display_readback.handle(), 1, &region);
  vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                      VK_ACCESS_HOST_READ_BIT);
}

}  // namespace renderer
