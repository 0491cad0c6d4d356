#include "renderer/gpu_timer.hpp"

#include "renderer/vulkan/vk_check.hpp"

namespace renderer {

GpuTimer::GpuTimer(const vkx::Device& device, std::uint32_t scopes)
    : device_(device.handle()), scopes_(scopes), period_ns_(device.info().timestamp_period_ns) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, families.data());
  const std::uint32_t bits = families[device.queue_family()].timestampValidBits;
  valid_mask_ = bits >= 64 ? ~0ull : ((1ull << bits) - 1);

  VkQueryPoolCreateInfo ci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  ci.queryType = VK_QUERY_TYPE_TIMESTAMP;
  ci.queryCount = 2 * scopes;
  VK_CHECK(vkCreateQueryPool(device_, &ci, nullptr, &pool_));
}

GpuTimer::~GpuTimer() { vkDestroyQueryPool(device_, pool_, nullptr); }

void GpuTimer::reset(VkCommandBuffer cmd) const { vkCmdResetQueryPool(cmd, pool_, 0, 2 * scopes_); }

void GpuTimer::begin(VkCommandBuffer cmd, std::uint32_t scope) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_, 2 * scope);
}

void GpuTimer::end(VkCommandBuffer cmd, std::uint32_t scope) const {
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_, 2 * scope + 1);
}

std::vector<double> GpuTimer::read_ms(const std::vector<bool>& recorded) const {
  std::vector<double> ms(scopes_, 0.0);
  for (std::uint32_t s = 0; s < scopes_; ++s) {
    if (!recorded[s]) continue;
    std::uint64_t ticks[2] = {0, 0};
    VK_CHECK(vkGetQueryPoolResults(device_, pool_, 2 * s, 2, sizeof(ticks), ticks, sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const std::uint64_t delta = (ticks[1] - ticks[0]) & valid_mask_;
    ms[s] = static_cast<double>(delta) * period_ns_ * 1e-6;
  }
  return ms;
}

}  // namespace renderer
