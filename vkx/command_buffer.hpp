// One primary command buffer recorded again and again (a frame's passes, one submission each),
// with the pool it comes from; the device submits it (Device::submit_and_wait).
#pragma once

#include "vkx/device.hpp"

#include <vulkan/vulkan.h>

namespace vkx {

class ReusableCommandBuffer {
 public:
  explicit ReusableCommandBuffer(const Device& device);
  ~ReusableCommandBuffer();
  ReusableCommandBuffer(const ReusableCommandBuffer&) = delete;
  ReusableCommandBuffer& operator=(const ReusableCommandBuffer&) = delete;

  // Resets the buffer and begins a recording to be submitted once.
  VkCommandBuffer begin();
  VkCommandBuffer handle() const { return commands_; }

 private:
  const Device& device_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
};

}  // namespace vkx
