// Vulkan failures become exceptions that name the call and the VkResult.
// Never an assert: a release build must report a lost device as clearly as a debug one.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace vkx {

const char* result_name(VkResult result);

class VulkanError : public std::runtime_error {
 public:
  VulkanError(const std::string& call, VkResult result)
      : std::runtime_error(call + " failed: " + result_name(result)), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

inline void check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw VulkanError(call, result);
}

}  // namespace vkx

// VK_CHECK(vkCreateBuffer(...)) throws vkx::VulkanError("vkCreateBuffer(...)", result).
#define VK_CHECK(expr) ::vkx::check((expr), #expr)
