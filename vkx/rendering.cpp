#include "vkx/rendering.hpp"

#include <vector>

namespace vkx {

void prepare_attachments(VkCommandBuffer cmd, std::span<const Image* const> colors, const Image* depth) {
  for (const Image* image : colors)
    transition(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  if (depth)
    transition(cmd, *depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
               VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

void colors_to_compute(VkCommandBuffer cmd, std::span<const Image* const> colors) {
  for (const Image* image : colors)
    transition(cmd, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

void undrawn_to_compute(VkCommandBuffer cmd, std::span<const Image* const> colors) {
  for (const Image* image : colors)
    transition(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

void begin_cleared_rendering(const Device& device, VkCommandBuffer cmd, std::span<const VkImageView> colors,
                             VkImageView depth, VkExtent2D extent, bool store_depth, ClearColors clear,
                             float clear_alpha, const VkViewport* viewport) {
  std::vector<VkRenderingAttachmentInfoKHR> color_attachments(colors.size());
  for (std::size_t i = 0; i < colors.size(); ++i) {
    VkRenderingAttachmentInfoKHR& a = color_attachments[i];
    a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR;
    a.imageView = colors[i];
    a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    a.loadOp = i == 0 || clear == ClearColors::all ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.clearValue.color = {{0.0f, 0.0f, 0.0f, clear_alpha}};
  }
  VkRenderingAttachmentInfoKHR depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  depth_attachment.imageView = depth;
  depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth_attachment.storeOp = store_depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth_attachment.clearValue.depthStencil = {1.0f, 0};

  const VkRect2D area{{0, 0}, extent};
  VkRenderingInfoKHR info{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
  info.renderArea = area;
  info.layerCount = 1;
  info.colorAttachmentCount = static_cast<std::uint32_t>(color_attachments.size());
  info.pColorAttachments = color_attachments.data();
  info.pDepthAttachment = depth ? &depth_attachment : nullptr;
  device.cmd_begin_rendering(cmd, &info);
  const VkViewport whole{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
  vkCmdSetViewport(cmd, 0, 1, viewport ? viewport : &whole);
  vkCmdSetScissor(cmd, 0, 1, &area);
}

}  // namespace vkx
