#include "renderer/frame_targets.hpp"

namespace renderer {
namespace {

vkx::Image color_target(const vkx::Device& device, VkFormat format, std::uint32_t w, std::uint32_t h) {
  return vkx::Image(device, {format, w, h, 1, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT});
}

}  // namespace

FrameTargets::FrameTargets(const vkx::Device& device, std::uint32_t w, std::uint32_t h)
    : width(w),
      height(h),
      position(color_target(device, kPositionFormat, w, h)),
      normal(color_target(device, kNormalFormat, w, h)),
      albedo(color_target(device, kAlbedoFormat, w, h)),
      depth(device, {kDepthFormat, w, h, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT}),
      display_target(device, {kDisplayFormat, w, h, 1,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT}) {
  const VkDeviceSize pixels = VkDeviceSize(w) * h;
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  linear = vkx::Buffer(device, pixels * 16, storage, vkx::MemoryUse::gpu_only);
  display = vkx::Buffer(device, pixels * 4, storage, vkx::MemoryUse::gpu_only);
  linear_readback = vkx::Buffer(device, pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vkx::MemoryUse::readback);
  display_readback = vkx::Buffer(device, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vkx::MemoryUse::readback);
}

ShadowAtlas::ShadowAtlas(const vkx::Device& device, std::uint32_t res, std::uint32_t n)
    : resolution(res),
      layers(n),
      depth(device, {kFormat, res, res, n, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                     VK_IMAGE_ASPECT_DEPTH_BIT, true}) {}

}  // namespace renderer
