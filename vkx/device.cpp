#include "vkx/device.hpp"

#include "vkx/vk_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>

#include <unistd.h>

namespace vkx {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::filesystem::path default_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "lpv-render";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "lpv-render";
  return {};
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  std::uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

DeviceInfo describe(VkPhysicalDevice physical) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physical, &props);
  DeviceInfo info;
  info.name = props.properties.deviceName;
  info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  info.api_version = props.properties.apiVersion;
  info.vendor_id = props.properties.vendorID;
  info.device_id = props.properties.deviceID;
  info.type = props.properties.deviceType;
  info.timestamp_period_ns = props.properties.limits.timestampPeriod;
  info.limits = props.properties.limits;
  info.uniform_branches = runs_uniform_branches(driver.driverID, driver.driverInfo);
  return info;
}

bool has_layer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_device_extension(VkPhysicalDevice physical, const char* name) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, exts.data());
  return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// A device we can use: Vulkan 1.2+, dynamic rendering, and a queue family with graphics,
// compute and timestamps.
std::string unusable_reason(VkPhysicalDevice physical, const DeviceInfo& info) {
  if (info.api_version < VK_API_VERSION_1_2) return "supports only Vulkan " + std::to_string(VK_API_VERSION_MAJOR(info.api_version)) + "." + std::to_string(VK_API_VERSION_MINOR(info.api_version));
  if (info.api_version < VK_API_VERSION_1_3 && !has_device_extension(physical, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME))
    return "lacks VK_KHR_dynamic_rendering";
  return {};
}

VkInstance create_plain_instance(bool validation, const void* next) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "lpv-render";
  app.apiVersion = VK_API_VERSION_1_3;
  std::vector<const char*> layers, extensions;
  if (validation) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);  // the layer's own
  }
  VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, next};
  ci.pApplicationInfo = &app;
  ci.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  ci.ppEnabledLayerNames = layers.data();
  ci.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  ci.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VK_CHECK(vkCreateInstance(&ci, nullptr, &instance));
  return instance;
}

}  // namespace

DeviceOptions DeviceOptions::from_environment() {
  DeviceOptions options;
  if (const char* dev = std::getenv("LPV_DEVICE")) options.selector = dev;
  if (const char* val = std::getenv("LPV_VALIDATION")) options.validation = std::string(val) == "1";
  if (const char* val = std::getenv("LPV_VALIDATION_SYNC")) options.synchronization_validation = std::string(val) != "0";
  const char* cache = std::getenv("LPV_PIPELINE_CACHE");
  if (cache && std::string(cache) == "off") {
    options.pipeline_cache_file.clear();
  } else if (cache && *cache) {
    options.pipeline_cache_file = cache;
  } else if (auto dir = default_cache_dir(); !dir.empty()) {
    options.pipeline_cache_file = dir / "pipeline-cache.bin";
  }
  return options;
}

std::vector<DeviceInfo> Device::enumerate() {
  VkInstance instance = create_plain_instance(false, nullptr);
  std::vector<DeviceInfo> infos;
  try {
    for (VkPhysicalDevice p : physical_devices(instance)) infos.push_back(describe(p));
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  return infos;
}

bool runs_uniform_branches(VkDriverId driver, const std::string& driver_info) {
  if (driver != VK_DRIVER_ID_MESA_LLVMPIPE) return true;
  // lavapipe reports 1 as its driverVersion whatever the release: Mesa's major version is read
  // from its info, "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)".
  int major = 0;
  return std::sscanf(driver_info.c_str(), "Mesa %d", &major) == 1 && major >= 25;
}

Device::Device(const DeviceOptions& options) : options_(options) {
  try {
    create_instance(options.validation, options.synchronization_validation);
    pick_physical_device(options.selector);
    create_device();
    load_pipeline_cache();
  } catch (...) {
    release();
    throw;
  }
}

Device::~Device() { release(); }

void Device::release() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    try {
      save_pipeline_cache();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lpv: could not save the pipeline cache: %s\n", e.what());
    }
    vkDestroyPipelineCache(device_, pipeline_cache_, nullptr);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, transient_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL Device::on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                        VkDebugUtilsMessageTypeFlagsEXT,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Device*>(user);
  const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
  std::string text = std::string("validation ") + level + ": " + (data->pMessage ? data->pMessage : "");
  std::fprintf(stderr, "%s\n", text.c_str());
  std::lock_guard lock(self->messages_mutex_);
  self->messages_.push_back(std::move(text));
  return VK_FALSE;
}

void Device::create_instance(bool validation, bool synchronization_validation) {
  if (validation && !has_layer(kValidationLayer))
    throw std::runtime_error(std::string("validation requested but ") + kValidationLayer +
                             " is not installed (Debian package vulkan-validationlayers)");
  // Synchronization validation too: lavapipe runs a command buffer's work in order, so a
  // missing barrier changes nothing there and shows only on a GPU that overlaps passes;
  // the layer finds it on any device (a barrier left out of propagation: 5 hazards at once).
  // The sanitizer build turns it off: the layer (1.3.239) leaks about 24 KB of it at exit.
  static const VkValidationFeatureEnableEXT kEnables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = synchronization_validation ? 1 : 0;
  features.pEnabledValidationFeatures = kEnables;
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &Device::on_debug_message;
  messenger.pUserData = this;
  features.pNext = &messenger;  // the instance's own messenger, for its creation and destruction
  instance_ = create_plain_instance(validation, validation ? &features : nullptr);
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw std::runtime_error("vkCreateDebugUtilsMessengerEXT is not available");
    VK_CHECK(create(instance_, &messenger, nullptr, &messenger_));
  }
}

void Device::pick_physical_device(const std::string& selector) {
  const auto devices = physical_devices(instance_);
  if (devices.empty()) throw std::runtime_error("no Vulkan device found (is mesa-vulkan-drivers installed?)");

  std::vector<DeviceInfo> infos;
  for (VkPhysicalDevice d : devices) infos.push_back(describe(d));
  auto listing = [&] {
    std::string s;
    for (std::size_t i = 0; i < infos.size(); ++i) s += "\n  [" + std::to_string(i) + "] " + infos[i].name;
    return s;
  };

  std::size_t chosen = infos.size();
  if (selector.empty()) {
    auto cpu = std::find_if(infos.begin(), infos.end(), [](const DeviceInfo& i) {
      return i.type == VK_PHYSICAL_DEVICE_TYPE_CPU || lowercase(i.name).find("llvmpipe") != std::string::npos;
    });
    chosen = cpu != infos.end() ? static_cast<std::size_t>(cpu - infos.begin()) : 0;
  } else if (is_index(selector)) {
    chosen = std::stoul(selector);
    if (chosen >= infos.size())
      throw std::runtime_error("device index " + selector + " out of range; devices:" + listing());
  } else {
    for (std::size_t i = 0; i < infos.size() && chosen == infos.size(); ++i)
      if (lowercase(infos[i].name).find(lowercase(selector)) != std::string::npos) chosen = i;
    if (chosen == infos.size()) throw std::runtime_error("no device matches '" + selector + "'; devices:" + listing());
  }

  if (auto why = unusable_reason(devices[chosen], infos[chosen]); !why.empty())
    throw std::runtime_error("device '" + infos[chosen].name + "' cannot be used: " + why);
  physical_ = devices[chosen];
  info_ = infos[chosen];
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

void Device::create_device() {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  auto family = std::find_if(families.begin(), families.end(), [&](const VkQueueFamilyProperties& f) {
    return (f.queueFlags & needed) == needed && f.timestampValidBits > 0;
  });
  if (family == families.end())
    throw std::runtime_error("device '" + info_.name + "' has no queue with graphics, compute and timestamps");
  queue_family_ = static_cast<std::uint32_t>(family - families.begin());

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_ci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_ci.queueFamilyIndex = queue_family_;
  queue_ci.queueCount = 1;
  queue_ci.pQueuePriorities = &priority;

  const bool core13 = info_.api_version >= VK_API_VERSION_1_3;
  VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.dynamicRendering = VK_TRUE;
  VkPhysicalDeviceDynamicRenderingFeaturesKHR dynamic_rendering{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
  dynamic_rendering.dynamicRendering = VK_TRUE;
  // The LPV passes accumulate in 64-bit fixed point with atomics, for bitwise determinism.
  VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
  vkGetPhysicalDeviceFeatures2(physical_, &supported);
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(physical_, &properties);
  info_.subgroup_size = subgroup.subgroupSize;
  // Subgroup shuffles sum the splats of a subgroup before its atomics (lpv_splat.glsl), and
  // share the cells of the indirect light's lookup between pixels (lpv_irradiance.glsl, in the
  // compute shading and the forward pass's fragment shader).
  const VkSubgroupFeatureFlags subgroup_needs =
      VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT;
  const VkShaderStageFlags subgroup_stages = VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  // Propagation lays a subgroup's lanes out as a block of columns at least 2 wide each way.
  const bool subgroup_ops = (subgroup.supportedOperations & subgroup_needs) == subgroup_needs &&
                            (subgroup.supportedStages & subgroup_stages) == subgroup_stages && subgroup.subgroupSize >= 4;
  if (!supported.features.shaderInt64 || !supported12.shaderBufferInt64Atomics ||
      !supported12.shaderSubgroupExtendedTypes || !subgroup_ops)
    throw std::runtime_error("device '" + info_.name + "' lacks 64-bit integer atomics or subgroup sums of them "
                             "(shaderInt64, shaderBufferInt64Atomics, shaderSubgroupExtendedTypes, subgroup "
                             "arithmetic, votes and shuffles in compute and fragment shaders, at least 4 lanes), which the LPV passes need "
                             "for deterministic accumulation and propagation");
  VkPhysicalDeviceFeatures features10{};
  features10.shaderInt64 = VK_TRUE;
  VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  features12.shaderBufferInt64Atomics = VK_TRUE;
  features12.shaderSubgroupExtendedTypes = VK_TRUE;
  features12.pNext = core13 ? static_cast<void*>(&features13) : static_cast<void*>(&dynamic_rendering);
  std::vector<const char*> extensions;
  if (!core13) extensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);

  VkDeviceCreateInfo ci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features12};
  ci.queueCreateInfoCount = 1;
  ci.pQueueCreateInfos = &queue_ci;
  ci.pEnabledFeatures = &features10;
  ci.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  ci.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_, &ci, nullptr, &device_));
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  cmd_begin_rendering = reinterpret_cast<PFN_vkCmdBeginRenderingKHR>(
      vkGetDeviceProcAddr(device_, core13 ? "vkCmdBeginRendering" : "vkCmdBeginRenderingKHR"));
  cmd_end_rendering = reinterpret_cast<PFN_vkCmdEndRenderingKHR>(
      vkGetDeviceProcAddr(device_, core13 ? "vkCmdEndRendering" : "vkCmdEndRenderingKHR"));
  if (!cmd_begin_rendering || !cmd_end_rendering) throw std::runtime_error("dynamic rendering entry points are missing");

  VkCommandPoolCreateInfo pool_ci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_ci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_ci.queueFamilyIndex = queue_family_;
  VK_CHECK(vkCreateCommandPool(device_, &pool_ci, nullptr, &transient_pool_));
  VkFenceCreateInfo fence_ci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device_, &fence_ci, nullptr, &fence_));
}

// The driver validates the blob's header itself; we additionally drop a blob written for
// another device so that a shared cache directory cannot feed one driver another's data.
void Device::load_pipeline_cache() {
  std::vector<char> blob;
  if (!options_.pipeline_cache_file.empty()) {
    std::ifstream in(options_.pipeline_cache_file, std::ios::binary);
    if (in) blob.assign(std::istreambuf_iterator<char>(in), {});
    VkPipelineCacheHeaderVersionOne header{};
    if (blob.size() >= sizeof(header)) std::memcpy(&header, blob.data(), sizeof(header));
    if (blob.size() < sizeof(header) || header.vendorID != info_.vendor_id || header.deviceID != info_.device_id) blob.clear();
  }
  VkPipelineCacheCreateInfo ci{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  ci.initialDataSize = blob.size();
  ci.pInitialData = blob.empty() ? nullptr : blob.data();
  if (vkCreatePipelineCache(device_, &ci, nullptr, &pipeline_cache_) != VK_SUCCESS) {
    ci.initialDataSize = 0;  // a corrupt cache file is not an error, only a slower start
    ci.pInitialData = nullptr;
    VK_CHECK(vkCreatePipelineCache(device_, &ci, nullptr, &pipeline_cache_));
  }
}

void Device::save_pipeline_cache() const {
  if (options_.pipeline_cache_file.empty() || !pipeline_cache_) return;
  std::size_t size = 0;
  VK_CHECK(vkGetPipelineCacheData(device_, pipeline_cache_, &size, nullptr));
  std::vector<char> blob(size);
  VK_CHECK(vkGetPipelineCacheData(device_, pipeline_cache_, &size, blob.data()));
  const auto& path = options_.pipeline_cache_file;
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  // Temporary file then rename: concurrent processes never read a half-written cache, and the
  // last to finish wins. Named by process and a random number: replicas in containers sharing
  // one volume may have the same process id.
  auto tmp = path;
  tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(std::random_device{}());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(blob.data(), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot rename pipeline cache into " + path.string());
  }
}

std::uint32_t Device::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                                  VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags want : {required | preferred, required}) {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  throw std::runtime_error("no Vulkan memory type with the required properties");
}

void Device::submit_and_wait(VkCommandBuffer commands) const {
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  VK_CHECK(vkResetFences(device_, 1, &fence_));
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
}

void Device::run_once(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = transient_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &commands));
  try {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    record(commands);
    VK_CHECK(vkEndCommandBuffer(commands));
    submit_and_wait(commands);
  } catch (...) {
    vkFreeCommandBuffers(device_, transient_pool_, 1, &commands);
    throw;
  }
  vkFreeCommandBuffers(device_, transient_pool_, 1, &commands);
}

std::vector<std::string> Device::validation_messages() const {
  std::lock_guard lock(messages_mutex_);
  return messages_;
}

void Device::clear_validation_messages() {
  std::lock_guard lock(messages_mutex_);
  messages_.clear();
}

}  // namespace vkx
