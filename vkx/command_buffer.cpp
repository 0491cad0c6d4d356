#include "vkx/command_buffer.hpp"

#include "vkx/vk_check.hpp"

namespace vkx {

ReusableCommandBuffer::ReusableCommandBuffer(const Device& device) : device_(device) {
  VkCommandPoolCreateInfo pool_ci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_ci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_ci.queueFamilyIndex = device.queue_family();
  VK_CHECK(vkCreateCommandPool(device.handle(), &pool_ci, nullptr, &pool_));
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  if (const VkResult r = vkAllocateCommandBuffers(device.handle(), &alloc, &commands_); r != VK_SUCCESS) {
    vkDestroyCommandPool(device.handle(), pool_, nullptr);
    ::vkx::check(r, "vkAllocateCommandBuffers");
  }
}

ReusableCommandBuffer::~ReusableCommandBuffer() { vkDestroyCommandPool(device_.handle(), pool_, nullptr); }

VkCommandBuffer ReusableCommandBuffer::begin() {
  VK_CHECK(vkResetCommandBuffer(commands_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
  return commands_;
}

}  // namespace vkx
