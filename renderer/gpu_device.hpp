// A device as code above the renderer holds it: opened from vkx::DeviceOptions, handed to a
// Renderer, described by a plain report. No Vulkan header comes with it, so the server and
// the tools keep Vulkan out of their code (tests/layers checks that the server does).
#pragma once

#include "vkx/device_options.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vkx {
class Device;
}

namespace renderer {

// The device's limits that bound what a request can ask for (image sizes, LPV grids, buffers).
struct DeviceLimits {
  std::uint32_t max_image_dimension_2d = 0;
  std::uint32_t max_image_dimension_3d = 0;
  std::uint32_t max_image_array_layers = 0;
  std::uint32_t max_framebuffer_width = 0;
  std::uint32_t max_framebuffer_height = 0;
  std::uint32_t max_color_attachments = 0;
  std::uint32_t max_uniform_buffer_range = 0;
  std::uint32_t max_storage_buffer_range = 0;
  std::uint32_t max_texel_buffer_elements = 0;
  std::uint32_t max_push_constants_size = 0;
  std::uint32_t max_bound_descriptor_sets = 0;
  std::uint32_t max_compute_shared_memory_size = 0;
  std::uint32_t max_compute_work_group_invocations = 0;
  std::array<std::uint32_t, 3> max_compute_work_group_size{};
  std::array<std::uint32_t, 3> max_compute_work_group_count{};
  bool timestamp_compute_and_graphics = false;
};

struct DeviceReport {
  std::string name;
  std::string driver;  // the driver's name and version as it reports them
  std::array<std::uint32_t, 3> api_version{};  // major, minor, patch
  std::uint32_t vendor_id = 0;
  std::uint32_t device_id = 0;
  std::string type;  // "discrete_gpu", "integrated_gpu", "virtual_gpu", "cpu" or "other"
  double timestamp_period_ns = 1.0;
  DeviceLimits limits;
};

class GpuDevice {
 public:
  explicit GpuDevice(const vkx::DeviceOptions& options);
  ~GpuDevice();
  GpuDevice(const GpuDevice&) = delete;
  GpuDevice& operator=(const GpuDevice&) = delete;

  // Every device the loader sees, in enumeration order (`--list-devices`).
  static std::vector<DeviceReport> enumerate();

  // For a Renderer (renderer.hpp declares it with vkx::Device, also incomplete there).
  const vkx::Device& vulkan() const { return *device_; }
  DeviceReport report() const;
  // The validation layer's messages so far (with vkx::DeviceOptions::validation).
  std::vector<std::string> validation_messages() const;

 private:
  std::unique_ptr<vkx::Device> device_;
};

}  // namespace renderer
