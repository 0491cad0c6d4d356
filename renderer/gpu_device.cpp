#include "renderer/gpu_device.hpp"

#include "vkx/device.hpp"

namespace renderer {
namespace {

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

std::array<std::uint32_t, 3> three(const std::uint32_t (&v)[3]) { return {v[0], v[1], v[2]}; }

DeviceReport report_of(const vkx::DeviceInfo& info) {
  const VkPhysicalDeviceLimits& l = info.limits;
  DeviceReport r;
  r.name = info.name;
  r.driver = info.driver;
  r.api_version = {VK_API_VERSION_MAJOR(info.api_version), VK_API_VERSION_MINOR(info.api_version),
                   VK_API_VERSION_PATCH(info.api_version)};
  r.vendor_id = info.vendor_id;
  r.device_id = info.device_id;
  r.type = type_name(info.type);
  r.timestamp_period_ns = info.timestamp_period_ns;
  r.limits = {l.maxImageDimension2D,
              l.maxImageDimension3D,
              l.maxImageArrayLayers,
              l.maxFramebufferWidth,
              l.maxFramebufferHeight,
              l.maxColorAttachments,
              l.maxUniformBufferRange,
              l.maxStorageBufferRange,
              l.maxTexelBufferElements,
              l.maxPushConstantsSize,
              l.maxBoundDescriptorSets,
              l.maxComputeSharedMemorySize,
              l.maxComputeWorkGroupInvocations,
              three(l.maxComputeWorkGroupSize),
              three(l.maxComputeWorkGroupCount),
              l.timestampComputeAndGraphics == VK_TRUE};
  return r;
}

}  // namespace

GpuDevice::GpuDevice(const vkx::DeviceOptions& options) : device_(std::make_unique<vkx::Device>(options)) {}

GpuDevice::~GpuDevice() = default;

std::vector<DeviceReport> GpuDevice::enumerate() {
  std::vector<DeviceReport> reports;
  for (const vkx::DeviceInfo& info : vkx::Device::enumerate()) reports.push_back(report_of(info));
  return reports;
}

DeviceReport GpuDevice::report() const { return report_of(device_->info()); }

std::vector<std::string> GpuDevice::validation_messages() const { return device_->validation_messages(); }

}  // namespace renderer
