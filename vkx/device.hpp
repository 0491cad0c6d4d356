// The long-lived Vulkan context of a process: instance, one physical device chosen by
// name or index (lavapipe by default), one queue that does graphics, compute and
// transfers, and a pipeline cache persisted on disk. No window system is involved.
#pragma once

#include "vkx/device_options.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace vkx {

struct DeviceInfo {
  std::string name;
  std::string driver;  // driver name and version string as the driver reports them
  std::uint32_t api_version = 0;
  std::uint32_t vendor_id = 0;
  std::uint32_t device_id = 0;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  double timestamp_period_ns = 1.0;
  VkPhysicalDeviceLimits limits{};
  // Runs only the taken side of a branch whose condition every lane of a subgroup shares.
  // lavapipe before Mesa 25 runs both sides under a lane mask (measured on 22.3, docs/lpv.md
  // "The driver"), so a shader's shortcut behind such a branch costs there instead of paying.
  bool uniform_branches = true;
  std::uint32_t subgroup_size = 0;  // lanes of a compute subgroup (VkPhysicalDeviceSubgroupProperties)
};

// DeviceInfo::uniform_branches for a driver: false for lavapipe before Mesa 25 (measured on
// 22.3 and 25.0 only; a Mesa version it cannot read counts as old).
bool runs_uniform_branches(VkDriverId driver, const std::string& driver_info);

class Device {
 public:
  explicit Device(const DeviceOptions& options);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  // Every device the loader sees, in enumeration order, for `--list-devices`.
  static std::vector<DeviceInfo> enumerate();

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkDevice handle() const { return device_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  VkPipelineCache pipeline_cache() const { return pipeline_cache_; }
  const DeviceInfo& info() const { return info_; }

  // A memory type allowed by `type_bits` with all `required` flags, preferring `preferred`.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred = 0) const;

  // Records `record` into a transient command buffer, submits it and waits.
  // Submission is not thread-safe: one render worker owns the device at a time.
  void run_once(const std::function<void(VkCommandBuffer)>& record) const;
  // Submits an already recorded command buffer and blocks until it completes.
  void submit_and_wait(VkCommandBuffer commands) const;

  // Dynamic rendering (core in 1.3, VK_KHR_dynamic_rendering on 1.2).
  PFN_vkCmdBeginRenderingKHR cmd_begin_rendering = nullptr;
  PFN_vkCmdEndRenderingKHR cmd_end_rendering = nullptr;

  // Validation messages seen so far (only with options.validation).
  std::vector<std::string> validation_messages() const;
  void clear_validation_messages();

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                         VkDebugUtilsMessageTypeFlagsEXT,
                                                         const VkDebugUtilsMessengerCallbackDataEXT*, void*);
  void create_instance(bool validation, bool synchronization_validation);
  void pick_physical_device(const std::string& selector);
  void create_device();
  void load_pipeline_cache();
  void save_pipeline_cache() const;  // atomically, to options.pipeline_cache_file
  void release();  // destroys every handle; safe on a partly constructed device

  DeviceOptions options_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  VkCommandPool transient_pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPipelineCache pipeline_cache_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  DeviceInfo info_;

  mutable std::mutex messages_mutex_;
  std::vector<std::string> messages_;
};

}  // namespace vkx
