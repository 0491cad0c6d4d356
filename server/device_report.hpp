// The device a render worker opened, as JSON for GET /v1/device.
#pragma once

#include "renderer/vulkan/device.hpp"

#include <nlohmann/json.hpp>

namespace server {

// The one place in server/ that reads Vulkan types: plain fields of DeviceInfo and its
// VkPhysicalDeviceLimits, no Vulkan calls.
nlohmann::json device_report(const vkx::DeviceInfo& info);

}  // namespace server
