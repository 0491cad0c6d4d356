// Device time per pass. Each pass is submitted on its own and waited for, so its time is
// its own: on a GPU from a pair of timestamp queries around its commands; on a CPU device
// (lavapipe) from the wall clock around the submission, because lavapipe may write a
// timestamp before its rasteriser has finished the work recorded ahead of it.
#pragma once

#include "vkx/device.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace renderer {

class PassTimer {
 public:
  explicit PassTimer(const vkx::Device& device);
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  // Bracket a pass's commands in its command buffer.
  void begin(VkCommandBuffer cmd) const;
  void end(VkCommandBuffer cmd) const;

  // Milliseconds the device spent on the pass, given the wall time of its submit-and-wait.
  double device_ms(double submit_wait_ms) const;

 private:
  VkDevice device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;  // null on CPU devices
  double period_ns_;
  std::uint64_t valid_mask_ = 0;
};

}  // namespace renderer
