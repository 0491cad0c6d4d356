#include "renderer/passes/rsm_pass.hpp"

#include "shaders/rsm.frag.h"
#include "shaders/rsm.vert.h"

#include <array>

namespace renderer {
namespace {

struct DrawConstants {
  std::uint32_t view;
  std::uint32_t material;
};

}  // namespace

RsmPass::RsmPass(const vkx::Device& device) : device_(device) {
  const VkShaderStageFlags vs_fs = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  vkx::PipelineLayoutDesc layout;
  layout.bindings = {vkx::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vs_fs),
                     vkx::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
                     vkx::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
  layout.push_constant_bytes = sizeof(DrawConstants);
  layout.push_constant_stages = vs_fs;
  vkx::GraphicsPipelineDesc g;
  g.vertex_spirv = spirv_rsm_vert;
  g.fragment_spirv = spirv_rsm_frag;
  g.vertex_input = {sizeof(scene::Vertex),
                    {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)},
                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)}}};
  g.color_formats = {RsmMaps::kPositionFormat, RsmMaps::kNormalFormat, RsmMaps::kFluxFormat};
  g.depth_format = RsmMaps::kDepthFormat;
  g.cull_mode = VK_CULL_MODE_NONE;  // the first surface the light meets, whichever way it faces
  pipeline_ = vkx::Pipeline(device, layout, g);
}

void RsmPass::record(VkCommandBuffer cmd, const GpuScene& scene, const RsmMaps& maps, const vkx::Buffer& views,
                     const vkx::Buffer& lights) const {
  vkx::DescriptorWriter(pipeline_.descriptor_set())
      .buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, views.handle())
      .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lights.handle())
      .buffer(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene.materials.handle())
      .apply(device_.handle());
  const std::array<const vkx::Image*, 3> colors{&maps.position, &maps.normal, &maps.flux};
  for (const vkx::Image* image : colors)
    vkx::transition(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  vkx::transition(cmd, maps.depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                  VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);

  const VkRect2D area{{0, 0}, {maps.resolution, maps.resolution}};
  const VkViewport viewport{0.0f, 0.0f, float(maps.resolution), float(maps.resolution), 0.0f, 1.0f};
  for (std::uint32_t layer = 0; layer < maps.layers; ++layer) {
    std::array<VkRenderingAttachmentInfoKHR, 3> color_attachments{};
    for (std::size_t i = 0; i < colors.size(); ++i) {
      auto& a = color_attachments[i];
      a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR;
      a.imageView = colors[i]->layer_view(layer);
      a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // position.w = 0 marks "nothing seen"
      a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      a.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    }
    VkRenderingAttachmentInfoKHR depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
    depth.imageView = maps.depth.layer_view(layer);
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfoKHR info{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
    info.renderArea = area;
    info.layerCount = 1;
    info.colorAttachmentCount = std::uint32_t(color_attachments.size());
    info.pColorAttachments = color_attachments.data();
    info.pDepthAttachment = &depth;
    device_.cmd_begin_rendering(cmd, &info);
    if (scene.index_count > 0) {
      pipeline_.bind(cmd);
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      vkCmdSetScissor(cmd, 0, 1, &area);
      scene.bind_geometry(cmd);
      for (const scene::Draw& draw : scene.draws) {
        pipeline_.push(cmd, DrawConstants{layer, draw.material});
        vkCmdDrawIndexed(cmd, draw.index_count, 1, draw.first_index, 0, 0);
      }
    }
    device_.cmd_end_rendering(cmd);
  }
  for (const vkx::Image* image : colors)
    vkx::transition(cmd, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

}  // namespace renderer
