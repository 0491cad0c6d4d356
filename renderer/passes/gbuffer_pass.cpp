#include "renderer/passes/gbuffer_pass.hpp"

#include "shaders/gbuffer.frag.h"
#include "shaders/gbuffer.vert.h"
#include "shaders/shared/camera_raster_interface.h"
#include "vkx/rendering.hpp"

#include <array>

namespace renderer {

namespace {

vkx::PipelineLayoutDesc gbuffer_layout(const TextureSetLayout& textures) {
  vkx::PipelineLayoutDesc layout;
  layout.bindings = {vkx::binding(gpu::CAMERA_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)};
  layout.draw_sets = {textures.handle()};
  layout.push_constant_bytes = sizeof(gpu::GpuDrawMaterial);
  layout.push_constant_stages = VK_SHADER_STAGE_FRAGMENT_BIT;
  return layout;
}

vkx::GraphicsPipelineDesc gbuffer_pipeline(MaterialVariant variant) {
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_gbuffer_vert;
  g.fragment_spirv = spirv_gbuffer_frag;
  g.fragment_specialization = {variant.double_sided, variant.textured};
  g.vertex_input = scene_vertex_input();
  g.color_formats = {GBuffer::kPositionFormat, GBuffer::kNormalFormat, GBuffer::kAlbedoFormat};
  g.depth_format = GBuffer::kDepthFormat;
  // Counter-clockwise front faces as in glTF: the projection's Y flip and Vulkan's
  // Y-down framebuffer cancel, so the winding arrives as it was authored.
  g.cull_mode = variant.double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  g.front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  return g;
}

}  // namespace

GBufferPass::GBufferPass(const vkx::Device& device, const TextureSetLayout& textures)
    : device_(device), pipelines_(device, gbuffer_layout(textures), gbuffer_pipeline) {
  pipelines_.get({});  // the variant every scene without textures uses, made with the others at start
}

void GBufferPass::record(VkCommandBuffer cmd, const GpuScene& scene, std::span<const std::uint32_t> order,
                         const GBuffer& target, const vkx::Buffer& frame) const {
  for (MaterialVariant variant : scene.variants_in_use)  // before any is bound
    vkx::DescriptorWriter(pipelines_.get(variant).descriptor_set())
        .buffer(gpu::CAMERA_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame.handle())
        .apply(device_.handle());
  const std::array<const vkx::Image*, 3> colors{&target.position, &target.normal, &target.albedo};
  vkx::prepare_attachments(cmd, colors, &target.depth);
  const std::array<VkImageView, 3> views{target.position.view(), target.normal.view(), target.albedo.view()};
  // Position's w = 0 marks pixels with no surface; normal and albedo are read only elsewhere.
  vkx::begin_cleared_rendering(device_, cmd, views, target.depth.view(), {target.width, target.height}, false,
                               vkx::ClearColors::first, 0.0f, &target.viewport);
  scene.draw_all(
      cmd, [&](MaterialVariant variant) -> const vkx::Pipeline& { return pipelines_.get(variant); },
      [&](const scene::Draw& draw) { return scene.draw_material(draw); }, order);
  device_.cmd_end_rendering(cmd);

  vkx::colors_to_compute(cmd, colors);
}

void GBufferPass::record_unused(VkCommandBuffer cmd, const GBuffer& target) {
  const std::array<const vkx::Image*, 3> colors{&target.position, &target.normal, &target.albedo};
  vkx::undrawn_to_compute(cmd, colors);
}

}  // namespace renderer
