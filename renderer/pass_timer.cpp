#include "renderer/pass_timer.hpp"

#include "vkx/vk_check.hpp"

#include <vector>

namespace renderer {

PassTimer::PassTimer(const vkx::Device& device)
    : device_(device.handle()), period_ns_(device.info().timestamp_period_ns) {
  if (device.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU) return;
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, families.data());
  const std::uint32_t bits = families[device.queue_family()].timestampValidBits;
  valid_mask_ = bits >= 64 ? ~0ull : ((1ull << bits) - 1);

  VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  ci.queryCount = 2;
  VK_CHECK(vkCreateQueryPool(device_, &ci, nullptr, &pool_));
}

PassTimer::~PassTimer() {
  if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

void PassTimer::begin(VkCommandBuffer cmd) const {
  if (!pool_) return;
  vkCmdResetQueryPool(cmd, pool_, 0, 2);
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, 0);
}

void PassTimer::end(VkCommandBuffer cmd) const {
  if (pool_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 1);
}

double PassTimer::device_ms(double submit_wait_ms) const {
  if (!pool_) return submit_wait_ms;
  std::uint64_t ticks[2] = {0, 0};
  VK_CHECK(vkGetQueryPoolResults(device_, pool_, 0, 2, sizeof(ticks), ticks, sizeof(std::uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  return static_cast<double>((ticks[1] - ticks[0]) & valid_mask_) * period_ns_ * 1e-6;
}

}  // namespace renderer
