// The per-resolution images and buffers of a frame, kept between requests of the same size.
#pragma once

#include "vkx/resources.hpp"

#include <cstdint>

namespace renderer {

// A G-buffer of the camera's view: world position with material id, normal and albedo (base
// colour times texture) per pixel, and the depth it was drawn with. `viewport` maps the
// camera's view onto it (a surfel G-buffer's texel covers several of the image's pixels).
struct GBuffer {
  static constexpr VkFormat kPositionFormat = VK_FORMAT_R32G32B32A32_SFLOAT;  // world xyz, material + 1
  static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr VkFormat kAlbedoFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // 8 bits lose dark albedos
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  GBuffer(const vkx::Device& device, std::uint32_t width, std::uint32_t height, VkViewport viewport);

  std::uint32_t width;
  std::uint32_t height;
  VkViewport viewport;
  vkx::Image position;
  vkx::Image normal;
  vkx::Image albedo;
  vkx::Image depth;
};

// The camera's surfel G-buffer for an image of `width` x `height` pixels: a texel per
// `stride` x `stride` block, as many as have their sampled pixel inside the image (at least
// one), and the viewport that puts texel (i, j)'s centre on the centre of the image's pixel
// (stride i + stride / 2, stride j + stride / 2).
struct SurfelSampling {
  std::uint32_t width;
  std::uint32_t height;
  VkViewport viewport;
};
SurfelSampling surfel_sampling(std::uint32_t width, std::uint32_t height, std::uint32_t stride);

struct FrameTargets {
  static constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_UNORM;  // the forward pass's target

  // `surfel_stride`: pixels (each way) per texel of the camera's surfel G-buffer.
  FrameTargets(const vkx::Device& device, std::uint32_t width, std::uint32_t height, std::uint32_t surfel_stride);

  std::uint32_t width;
  std::uint32_t height;
  GBuffer camera;                // the deferred shading's G-buffer; the forward pass draws with its depth
  GBuffer surfels;               // the camera's surfels for the geometry volume (about 128 rows)
  vkx::Image display_target;     // the forward pass draws the display image here
  vkx::Buffer linear;            // vec4 per pixel, row 0 = top: the linear HDR image
  vkx::Buffer display;           // RGBA8 per pixel: the display-encoded image
  vkx::Buffer linear_readback;   // host copies of the two
  vkx::Buffer display_readback;
};

// Depth maps of every light, one layer per shadow view, all at one resolution.
struct ShadowAtlas {
  static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;

  ShadowAtlas(const vkx::Device& device, std::uint32_t resolution, std::uint32_t layers);

  std::uint32_t resolution;
  std::uint32_t layers;
  vkx::Image depth;
};

}  // namespace renderer
