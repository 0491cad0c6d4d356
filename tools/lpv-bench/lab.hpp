// Every device, renderer and workbench of one command, made and destroyed in the right order.
#pragma once

#include "bench_options.hpp"
#include "renderer/accuracy/workbench.hpp"
#include "renderer/renderer.hpp"
#include "renderer/vulkan/device.hpp"

namespace bench {

struct Lab {
  explicit Lab(const Options& options)
      : device([&] {
          vkx::DeviceOptions device_options = vkx::DeviceOptions::from_environment();
          if (options.device) device_options.selector = *options.device;
          return device_options;
        }()),
        renderer(device, {.test_slowdown = options.test_slowdown}),
        bench(renderer) {}
  vkx::Device device;
  renderer::Renderer renderer;
  accuracy::Workbench bench;
};

}  // namespace bench
