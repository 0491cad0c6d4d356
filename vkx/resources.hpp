// Move-only owners of buffers and images with their memory. One allocation per resource:
// a frame has a handful of them, so a sub-allocator would be complexity without payoff.
#pragma once

#include "vkx/device.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace vkx {

enum class MemoryUse {
  gpu_only,  // device-local
  upload,    // host-visible and coherent, persistently mapped
  readback,  // host-visible, cached if available, persistently mapped
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);
  ~Buffer();
  Buffer(Buffer&& other) noexcept { *this = std::move(other); }
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

  // Host access for upload and readback buffers.
  void write(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  const void* mapped() const { return mapped_; }
  void invalidate() const;  // makes device writes visible to the host (no-op when coherent)

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  bool coherent_ = true;
};

// A device-local buffer of 16-byte texels (RGBA32F, or RGBA32UI for 64-bit integer sums),
// read through a storage texel buffer view (imageBuffer: lavapipe gathers such texels with
// vector loads, where it reads a storage buffer at scattered offsets one lane at a time) and
// written as a storage buffer (atomics, or texels as two 64-bit halves, texel_store.glsl:
// lavapipe scatters those a lane at a time in one loop, where an image store takes one loop
// per channel).
class TexelBuffer {
 public:
  static constexpr VkDeviceSize kTexelBytes = 16;

  TexelBuffer() = default;
  TexelBuffer(const Device& device, VkDeviceSize texels, VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT);
  ~TexelBuffer();
  TexelBuffer(TexelBuffer&& other) noexcept { *this = std::move(other); }
  TexelBuffer& operator=(TexelBuffer&& other) noexcept;

  const Buffer& buffer() const { return buffer_; }
  VkBufferView view() const { return view_; }
  VkDeviceSize texels() const { return buffer_.size() / kTexelBytes; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  Buffer buffer_;
  VkBufferView view_ = VK_NULL_HANDLE;
};

struct ImageDesc {
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::uint32_t width = 1;
  std::uint32_t height = 1;
  std::uint32_t layers = 1;
  VkImageUsageFlags usage = 0;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  bool array = false;  // view() is a 2D array view even with one layer (for sampler2DArray)
  std::uint32_t depth = 1;  // with volume: a 3D image of this depth (layers stays 1)
  bool volume = false;
  std::uint32_t mip_levels = 1;  // view() covers all of them
};

class Image {
 public:
  Image() = default;
  Image(const Device& device, const ImageDesc& desc);
  ~Image();
  Image(Image&& other) noexcept { *this = std::move(other); }
  Image& operator=(Image&& other) noexcept;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }  // all layers (2D array view when layers > 1)
  VkImageView layer_view(std::uint32_t layer) const { return layer_views_.at(layer); }
  const ImageDesc& desc() const { return desc_; }
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> layer_views_;
  ImageDesc desc_;
};

// A sampler clamped to the edge, filtering nearest or linear, of one mip level. Or any
// sampler, from its create info.
class Sampler {
 public:
  Sampler() = default;
  Sampler(const Device& device, VkFilter filter);
  Sampler(const Device& device, const VkSamplerCreateInfo& create_info);
  ~Sampler();
  Sampler(Sampler&& other) noexcept { *this = std::move(other); }
  Sampler& operator=(Sampler&& other) noexcept;

  VkSampler handle() const { return sampler_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

// A device-local buffer filled with `bytes` through a staging copy.
Buffer upload_buffer(const Device& device, std::span<const std::byte> bytes, VkBufferUsageFlags usage);

// Layout transition of all layers of a colour or depth image, with full-pipeline scopes
// given by the caller.
void transition(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags src_stage, VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                VkAccessFlags dst_access);

// Compute writes made visible to later compute reads and writes: between dependent dispatches.
void compute_barrier(VkCommandBuffer cmd);

// A global memory barrier between two pipeline stages.
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stage, VkAccessFlags dst_access);

}  // namespace vkx
