// GPU time per pass from timestamp queries: one begin/end pair per scope and frame.
#pragma once

#include "renderer/vulkan/device.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace renderer {

class GpuTimer {
 public:
  GpuTimer(const vkx::Device& device, std::uint32_t scopes);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void reset(VkCommandBuffer cmd) const;  // before the first scope of a frame
  void begin(VkCommandBuffer cmd, std::uint32_t scope) const;
  void end(VkCommandBuffer cmd, std::uint32_t scope) const;

  // Milliseconds of each scope of the last completed frame; scopes not recorded give 0.
  std::vector<double> read_ms(const std::vector<bool>& recorded) const;

 private:
  VkDevice device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::uint32_t scopes_;
  double period_ns_;
  std::uint64_t valid_mask_;
};

}  // namespace renderer
