// How to open a device (vkx::Device), without Vulkan: what code above the renderer (the
// server, the tools) sets, so that it need not include a Vulkan header.
#pragma once

#include <filesystem>
#include <string>

namespace vkx {

struct DeviceOptions {
  // Empty: lavapipe (llvmpipe) if present, else the first device. A decimal number picks
  // that index of the enumeration; anything else is a case-insensitive substring of the name.
  std::string selector;
  bool validation = false;  // Khronos validation layer; every message is recorded
  // With validation, the layer's synchronization validation too (device.cpp says why).
  bool synchronization_validation = true;
  std::filesystem::path pipeline_cache_file;  // empty: the cache lives only in memory

  // LPV_DEVICE, LPV_VALIDATION=1, LPV_VALIDATION_SYNC=0 and LPV_PIPELINE_CACHE (a file, or
  // "off"); the cache defaults to $XDG_CACHE_HOME/lpv-render (or ~/.cache/lpv-render).
  static DeviceOptions from_environment();
};

}  // namespace vkx
