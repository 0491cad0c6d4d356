#include "renderer/passes/gbuffer_pass.hpp"

#include "shaders/gbuffer.frag.h"
#include "shaders/gbuffer.vert.h"

#include <array>

namespace renderer {

GBufferPass::GBufferPass(const vkx::Device& device) : device_(device) {
  vkx::PipelineLayoutDesc layout;
  layout.bindings = {vkx::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT),
                     vkx::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
  layout.push_constant_bytes = sizeof(std::uint32_t);
  layout.push_constant_stages = VK_SHADER_STAGE_FRAGMENT_BIT;
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_gbuffer_vert;
  g.fragment_spirv = spirv_gbuffer_frag;
  g.vertex_input = {sizeof(scene::Vertex),
                    {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)},
                     {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)}}};
  g.color_formats = {FrameTargets::kPositionFormat, FrameTargets::kNormalFormat, FrameTargets::kAlbedoFormat};
  g.depth_format = FrameTargets::kDepthFormat;
  g.cull_mode = VK_CULL_MODE_BACK_BIT;
  // Counter-clockwise front faces as in glTF: the projection's Y flip and Vulkan's
  // Y-down framebuffer cancel, so the winding arrives as it was authored.
  g.front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  pipeline_ = vkx::Pipeline(device, layout, g);
}

void GBufferPass::record(VkCommandBuffer cmd, const GpuScene& scene, const FrameTargets& targets,
                         const vkx::Buffer& frame) const {
  vkx::DescriptorWriter(pipeline_.descriptor_set())
      .buffer(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame.handle())
      .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene.materials.handle())
      .apply(device_.handle());

  const std::array<const vkx::Image*, 3> colors{&targets.position, &targets.normal, &targets.albedo};
  for (const vkx::Image* image : colors)
    vkx::transition(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  vkx::transition(cmd, targets.depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                  VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);

  std::array<VkRenderingAttachmentInfoKHR, 3> color_attachments{};
  for (std::size_t i = 0; i < colors.size(); ++i) {
    auto& a = color_attachments[i];
    a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR;
    a.imageView = colors[i]->view();
    a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // position.w = 0 marks "no surface"
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
  }
  VkRenderingAttachmentInfoKHR depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  depth.imageView = targets.depth.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};

  const VkRect2D area{{0, 0}, {targets.width, targets.height}};
  VkRenderingInfoKHR info{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
  info.renderArea = area;
  info.layerCount = 1;
  info.colorAttachmentCount = static_cast<std::uint32_t>(color_attachments.size());
  info.pColorAttachments = color_attachments.data();
  info.pDepthAttachment = &depth;
  device_.cmd_begin_rendering(cmd, &info);
  if (scene.index_count > 0) {
    const VkViewport viewport{0.0f, 0.0f, float(targets.width), float(targets.height), 0.0f, 1.0f};
    pipeline_.bind(cmd);
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
    scene.bind_geometry(cmd);
    for (const scene::Draw& draw : scene.draws) {
      pipeline_.push(cmd, draw.material);
      vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, 0, 0);
    }
  }
  device_.cmd_end_rendering(cmd);

  for (const vkx::Image* image : colors)
    vkx::transition(cmd, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

}  // namespace renderer
