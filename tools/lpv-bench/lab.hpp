// Every device, renderer and workbench of one command, made and destroyed in the right order.
#pragma once

#include "bench_options.hpp"
#include "lab/accuracy/workbench.hpp"
#include "renderer/gpu_device.hpp"
#include "renderer/renderer.hpp"

namespace bench {

struct Lab {
  explicit Lab(const Options& options)
      : device([&] {
          vkx::DeviceOptions device_options = vkx::DeviceOptions::from_environment();
          if (options.device) device_options.selector = *options.device;
          return device_options;
        }()),
        renderer(device.vulkan(), {.test_slowdown = options.test_slowdown}),
        bench(renderer) {}
  renderer::GpuDevice device;
  renderer::Renderer renderer;
  accuracy::Workbench bench;
};

}  // namespace bench
