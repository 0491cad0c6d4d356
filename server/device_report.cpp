#include "server/device_report.hpp"

#include <cstdio>
#include <string>

namespace server {
namespace {

std::string version_text(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

std::string hex_id(std::uint32_t id) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%04x", id);
  return text;
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

}  // namespace

nlohmann::json device_report(const vkx::DeviceInfo& info) {
  const VkPhysicalDeviceLimits& l = info.limits;
  // The limits that bound what a request can ask for (image sizes, LPV grids, buffers).
  const nlohmann::json limits = {
      {"max_image_dimension_2d", l.maxImageDimension2D},
      {"max_image_dimension_3d", l.maxImageDimension3D},
      {"max_image_array_layers", l.maxImageArrayLayers},
      {"max_framebuffer_width", l.maxFramebufferWidth},
      {"max_framebuffer_height", l.maxFramebufferHeight},
      {"max_color_attachments", l.maxColorAttachments},
      {"max_uniform_buffer_range", l.maxUniformBufferRange},
      {"max_storage_buffer_range", l.maxStorageBufferRange},
      {"max_texel_buffer_elements", l.maxTexelBufferElements},
      {"max_push_constants_size", l.maxPushConstantsSize},
      {"max_bound_descriptor_sets", l.maxBoundDescriptorSets},
      {"max_compute_shared_memory_size", l.maxComputeSharedMemorySize},
      {"max_compute_work_group_invocations", l.maxComputeWorkGroupInvocations},
      {"max_compute_work_group_size",
       {l.maxComputeWorkGroupSize[0], l.maxComputeWorkGroupSize[1], l.maxComputeWorkGroupSize[2]}},
      {"max_compute_work_group_count",
       {l.maxComputeWorkGroupCount[0], l.maxComputeWorkGroupCount[1], l.maxComputeWorkGroupCount[2]}},
      {"timestamp_compute_and_graphics", l.timestampComputeAndGraphics == VK_TRUE},
  };
  return {{"name", info.name},
          {"driver", info.driver},
          {"api_version", version_text(info.api_version)},
          {"vendor_id", hex_id(info.vendor_id)},
          {"device_id", hex_id(info.device_id)},
          {"type", type_name(info.type)},
          {"timestamp_period_ns", info.timestamp_period_ns},
          {"limits", limits}};
}

}  // namespace server
