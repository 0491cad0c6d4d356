#include "renderer/frame_targets.hpp"

namespace renderer {
namespace {

vkx::Image color_target(const vkx::Device& device, VkFormat format, std::uint32_t w, std::uint32_t h) {
  return vkx::Image(device, {format, w, h, 1, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT});
}

}  // namespace

GBuffer::GBuffer(const vkx::Device& device, std::uint32_t w, std::uint32_t h, VkViewport vp)
    : width(w),
      height(h),
      viewport(vp),
      position(color_target(device, kPositionFormat, w, h)),
      normal(color_target(device, kNormalFormat, w, h)),
      albedo(color_target(device, kAlbedoFormat, w, h)),
      depth(device, {kDepthFormat, w, h, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT}) {}

SurfelSampling surfel_sampling(std::uint32_t width, std::uint32_t height, std::uint32_t stride) {
  // Blocks along `pixels` whose sampled pixel, stride / 2 into the block, is inside the image.
  const auto blocks = [stride](std::uint32_t pixels) {
    return pixels > stride / 2 ? (pixels - stride / 2 - 1) / stride + 1 : 1;
  };
  // The view spans pixels / stride texels, shifted so that texel i's centre falls on pixel
  // stride i + stride / 2's: (i + 1/2 - origin) stride = stride i + stride / 2 + 1/2.
  const float s = float(stride);
  const float origin = 0.5f - (float(stride / 2) + 0.5f) / s;
  return {blocks(width), blocks(height), VkViewport{origin, origin, float(width) / s, float(height) / s, 0.0f, 1.0f}};
}

FrameTargets::FrameTargets(const vkx::Device& device, std::uint32_t w, std::uint32_t h, std::uint32_t surfel_stride)
    : width(w),
      height(h),
      camera(device, w, h, VkViewport{0.0f, 0.0f, float(w), float(h), 0.0f, 1.0f}),
      surfels([&] {
        const SurfelSampling sampling = surfel_sampling(w, h, surfel_stride);
        return GBuffer(device, sampling.width, sampling.height, sampling.viewport);
      }()),
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
