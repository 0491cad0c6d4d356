#include "vkx/resources.hpp"

#include "vkx/vk_check.hpp"

#include <cstring>
#include <stdexcept>

namespace vkx {
namespace {

VkDeviceMemory allocate(const Device& device, const VkMemoryRequirements& req, VkMemoryPropertyFlags required,
                        VkMemoryPropertyFlags preferred, VkMemoryPropertyFlags* actual) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = device.memory_type(req.memoryTypeBits, required, preferred);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateMemory(device.handle(), &alloc, nullptr, &memory));
  if (actual) {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(device.physical(), &props);
    *actual = props.memoryTypes[alloc.memoryTypeIndex].propertyFlags;
  }
  return memory;
}

}  // namespace

Buffer::Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use)
    : device_(device.handle()), size_(size) {
  if (size == 0) throw std::invalid_argument("Buffer: size must be positive");
  VkBufferCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  ci.size = size;
  ci.usage = usage;
  ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(device_, &ci, nullptr, &buffer_));
  try {
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, buffer_, &req);
    VkMemoryPropertyFlags required = 0, preferred = 0, actual = 0;
    switch (use) {
      case MemoryUse::gpu_only: preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT; break;
      case MemoryUse::upload: required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT; break;
      case MemoryUse::readback:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        break;
    }
    memory_ = allocate(device, req, required, preferred, &actual);
    VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
    if (use != MemoryUse::gpu_only) {
      VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
      coherent_ = (actual & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    }
  } catch (...) {
    release();
    throw;
  }
}

TexelBuffer::TexelBuffer(const Device& device, VkDeviceSize texels, VkFormat format)
    : device_(device.handle()),
      buffer_(device, texels * kTexelBytes,
              VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
              MemoryUse::gpu_only) {
  VkBufferViewCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  ci.buffer = buffer_.handle();
  ci.format = format;
  ci.range = VK_WHOLE_SIZE;
  VK_CHECK(vkCreateBufferView(device_, &ci, nullptr, &view_));
}

TexelBuffer::~TexelBuffer() { release(); }

TexelBuffer& TexelBuffer::operator=(TexelBuffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::move(other.buffer_);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void TexelBuffer::release() {
  if (view_) vkDestroyBufferView(device_, view_, nullptr);
  view_ = VK_NULL_HANDLE;
  buffer_ = Buffer();
}

Buffer::~Buffer() { release(); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
    coherent_ = other.coherent_;
  }
  return *this;
}

void Buffer::release() {
  if (!device_) return;
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);  // also unmaps
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

void Buffer::write(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (!mapped_) throw std::logic_error("Buffer::write on a buffer that is not host-visible");
  if (offset + bytes > size_) throw std::out_of_range("Buffer::write past the end");
  std::memcpy(static_cast<std::byte*>(mapped_) + offset, data, bytes);
}

void Buffer::invalidate() const {
  if (coherent_ || !mapped_) return;
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
  range.memory = memory_;
  range.size = VK_WHOLE_SIZE;
  VK_CHECK(vkInvalidateMappedMemoryRanges(device_, 1, &range));
}

Image::Image(const Device& device, const ImageDesc& desc) : device_(device.handle()), desc_(desc) {
  VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ci.imageType = desc.volume ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  ci.format = desc.format;
  ci.extent = {desc.width, desc.height, desc.volume ? desc.depth : 1};
  ci.mipLevels = desc.mip_levels;
  ci.arrayLayers = desc.layers;
  ci.samples = VK_SAMPLE_COUNT_1_BIT;
  ci.tiling = VK_IMAGE_TILING_OPTIMAL;
  ci.usage = desc.usage;
  ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(device_, &ci, nullptr, &image_));
  try {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    memory_ = allocate(device, req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, nullptr);
    VK_CHECK(vkBindImageMemory(device_, image_, memory_, 0));

    auto make_view = [&](VkImageViewType type, std::uint32_t first, std::uint32_t count) {
      VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      vci.image = image_;
      vci.viewType = type;
      vci.format = desc.format;
      vci.subresourceRange = {desc.aspect, 0, desc.mip_levels, first, count};
      VkImageView view = VK_NULL_HANDLE;
      VK_CHECK(vkCreateImageView(device_, &vci, nullptr, &view));
      return view;
    };
    if (desc.volume)
      view_ = make_view(VK_IMAGE_VIEW_TYPE_3D, 0, 1);
    else
      view_ = make_view(desc.layers > 1 || desc.array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D, 0, desc.layers);
    if (desc.layers > 1 || desc.array)
      for (std::uint32_t l = 0; l < desc.layers; ++l) layer_views_.push_back(make_view(VK_IMAGE_VIEW_TYPE_2D, l, 1));
    else
      layer_views_.push_back(view_);
  } catch (...) {
    release();
    throw;
  }
}

Image::~Image() { release(); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    layer_views_ = std::move(other.layer_views_);
    other.layer_views_.clear();
    desc_ = other.desc_;
  }
  return *this;
}

void Image::release() {
  if (!device_) return;
  for (VkImageView v : layer_views_)
    if (v != view_) vkDestroyImageView(device_, v, nullptr);
  layer_views_.clear();
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

Buffer upload_buffer(const Device& device, std::span<const std::byte> bytes, VkBufferUsageFlags usage) {
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes.size(), 16);  // empty scenes still bind a buffer
  Buffer staging(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::upload);
  if (!bytes.empty()) staging.write(bytes.data(), bytes.size());
  Buffer target(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::gpu_only);
  device.run_once([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cmd, staging.handle(), target.handle(), 1, &region);
  });
  return target;
}

Sampler::Sampler(const Device& device, VkFilter filter) : device_(device.handle()) {
  VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  ci.magFilter = filter;
  ci.minFilter = filter;
  ci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  ci.addressModeU = ci.addressModeV = ci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  ci.maxLod = 0.0f;
  VK_CHECK(vkCreateSampler(device_, &ci, nullptr, &sampler_));
}

Sampler::Sampler(const Device& device, const VkSamplerCreateInfo& create_info) : device_(device.handle()) {
  VK_CHECK(vkCreateSampler(device_, &create_info, nullptr, &sampler_));
}

Sampler::~Sampler() {
  if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
    device_ = other.device_;
    sampler_ = other.sampler_;
    other.sampler_ = VK_NULL_HANDLE;
  }
  return *this;
}

void transition(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags src_stage, VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                VkAccessFlags dst_access) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.handle();
  barrier.subresourceRange = {image.desc().aspect, 0, image.desc().mip_levels, 0, image.desc().layers};
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                    VkPipelineStageFlags dst_stage, VkAccessFlags dst_access) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void compute_barrier(VkCommandBuffer cmd) {
  memory_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

}  // namespace vkx
