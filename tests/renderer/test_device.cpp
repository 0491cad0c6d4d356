// The device layer: errors that name the call and the VkResult, device selection, and a
// pipeline cache file that survives restarts and corruption.
#include "gpu_test.hpp"

#include "vkx/resources.hpp"
#include "vkx/vk_check.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace {

TEST(VkCheck, FailureNamesTheCallAndTheResult) {
  try {
    VK_CHECK(VK_ERROR_DEVICE_LOST);
    FAIL() << "expected a VulkanError";
  } catch (const vkx::VulkanError& e) {
    EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
    EXPECT_STREQ(e.what(), "VK_ERROR_DEVICE_LOST failed: VK_ERROR_DEVICE_LOST");
  }
  EXPECT_STREQ(vkx::result_name(VK_ERROR_OUT_OF_DEVICE_MEMORY), "VK_ERROR_OUT_OF_DEVICE_MEMORY");
  EXPECT_NO_THROW(VK_CHECK(VK_SUCCESS));
}

TEST(DeviceSelection, UnknownNameOrIndexListsTheDevices) {
  for (const char* selector : {"no-such-device", "97"}) {
    vkx::DeviceOptions options;
    options.selector = selector;
    try {
      vkx::Device device(options);
      FAIL() << "expected an error for " << selector;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("devices:"), std::string::npos) << e.what();
    }
  }
}

TEST(DeviceSelection, DefaultIsTheCpuDeviceWhenPresent) {
  const auto devices = vkx::Device::enumerate();
  ASSERT_FALSE(devices.empty());
  const bool has_cpu = std::any_of(devices.begin(), devices.end(),
                                   [](const vkx::DeviceInfo& d) { return d.type == VK_PHYSICAL_DEVICE_TYPE_CPU; });
  if (!has_cpu) GTEST_SKIP() << "no CPU Vulkan device here";
  vkx::Device device(vkx::DeviceOptions{});
  EXPECT_EQ(device.info().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
  EXPECT_GE(device.info().api_version, VK_API_VERSION_1_2);
}

TEST(DeviceInfo, LavapipeBeforeMesa25RunsBothSidesOfAUniformBranch) {
  EXPECT_TRUE(vkx::runs_uniform_branches(VK_DRIVER_ID_MESA_LLVMPIPE, "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"));
  EXPECT_TRUE(vkx::runs_uniform_branches(VK_DRIVER_ID_MESA_LLVMPIPE, "Mesa 26.1.0"));
  EXPECT_FALSE(vkx::runs_uniform_branches(VK_DRIVER_ID_MESA_LLVMPIPE, "Mesa 22.3.6 (LLVM 15.0.6)"));
  EXPECT_FALSE(vkx::runs_uniform_branches(VK_DRIVER_ID_MESA_LLVMPIPE, "llvmpipe, version unknown"));
  EXPECT_TRUE(vkx::runs_uniform_branches(VK_DRIVER_ID_NVIDIA_PROPRIETARY, "580.159.04"));
  // What this machine's lavapipe says: install-deps.sh installs Mesa 25 or later.
  const auto& info = gpu_test::device().info();
  if (info.type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    EXPECT_TRUE(info.uniform_branches) << info.driver << ": the shared lookup of the indirect light is off";
  }
}

TEST(PipelineCache, IsWrittenOnExitAndACorruptFileIsIgnored) {
  const auto dir = std::filesystem::temp_directory_path() / ("lpv-cache-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  vkx::DeviceOptions options;
  options.pipeline_cache_file = dir / "cache.bin";
  {
    vkx::Device device(options);
    renderer::Renderer renderer(device);  // creates every pipeline through the cache
  }
  ASSERT_TRUE(std::filesystem::exists(options.pipeline_cache_file));
  EXPECT_GE(std::filesystem::file_size(options.pipeline_cache_file), sizeof(VkPipelineCacheHeaderVersionOne));

  std::ofstream(options.pipeline_cache_file, std::ios::binary | std::ios::trunc) << "not a pipeline cache";
  {
    vkx::Device device(options);
    renderer::Renderer renderer(device);
    api::RenderRequest request;
    request.output.width = request.output.height = 16;
    EXPECT_EQ(renderer.render(request).display.pixels.size(), 16u * 16u * 4u);
  }
  std::filesystem::remove_all(dir);
}

TEST(DeviceOptions, SynchronizationValidationIsOnUnlessTheEnvironmentSaysZero) {
  const char* saved = std::getenv("LPV_VALIDATION_SYNC");
  const std::string restore = saved ? saved : "";
  ::unsetenv("LPV_VALIDATION_SYNC");
  EXPECT_TRUE(vkx::DeviceOptions::from_environment().synchronization_validation);
  ::setenv("LPV_VALIDATION_SYNC", "0", 1);
  EXPECT_FALSE(vkx::DeviceOptions::from_environment().synchronization_validation);
  ::setenv("LPV_VALIDATION_SYNC", "1", 1);
  EXPECT_TRUE(vkx::DeviceOptions::from_environment().synchronization_validation);
  if (saved) {
    ::setenv("LPV_VALIDATION_SYNC", restore.c_str(), 1);
  } else {
    ::unsetenv("LPV_VALIDATION_SYNC");
  }
}

// The GPU tests fail on any validation message; this one checks that the layer is looking,
// synchronization included. Two writes to one buffer with no barrier between them may
// overlap on a GPU, though lavapipe runs them in order.
TEST(Validation, ReportsTwoWritesWithoutABarrierBetweenThem) {
  vkx::Device& device = gpu_test::device();
  device.clear_validation_messages();
  {
    vkx::Buffer buffer(device, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vkx::MemoryUse::gpu_only);
    device.run_once([&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 0u);
      vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, 1u);
    });
  }
  const auto messages = device.validation_messages();
  device.clear_validation_messages();
  ASSERT_FALSE(messages.empty()) << "no validation message: is synchronization validation on?";
  EXPECT_NE(messages.front().find("SYNC-HAZARD-WRITE-AFTER-WRITE"), std::string::npos) << messages.front();
}

class EdgeScenes : public gpu_test::GpuTest {};

TEST_F(EdgeScenes, EmptySceneWithoutLightsRendersBlackAndSkipsShadows) {
  scene::Scene empty = scene::SceneBuilder("empty").build();
  api::Camera camera;
  const auto result = gpu_test::renderer().render(empty, gpu_test::linear_request(32, 24, camera),
                                                  renderer::kReadbackLinear | renderer::kReadbackDisplay);
  for (float v : result.linear.pixels) ASSERT_EQ(v, 0.0f);
  EXPECT_EQ(result.display.pixels.size(), 32u * 24u * 4u);
  EXPECT_FALSE(result.stats.passes[0].ran);
  EXPECT_EQ(result.stats.passes[0].reason, "no light reaches the scene");
}

TEST_F(EdgeScenes, ZeroIntensityLightGivesBlackLitViewAndNoShadowMap) {
  api::RenderRequest request;
  request.output.width = request.output.height = 64;
  request.light_edits.push_back({});
  request.light_edits[0].intensity = 0.0f;
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackLinear);
  for (std::size_t i = 0; i < result.linear.pixels.size(); i += 4) ASSERT_EQ(result.linear.pixels[i], 0.0f);
  EXPECT_FALSE(result.stats.passes[0].ran);
}

// A PNG is shaded by the forward pass, which samples the shadow maps in its fragment shader;
// with the shadow pass skipped, the maps' layout transition is recorded just before it in
// the same command buffer and must reach the fragment stage (synchronization validation
// said so on the glTF corpus when it reached compute only).
TEST_F(EdgeScenes, ForwardPassAfterASkippedShadowPassIsSynchronized) {
  api::RenderRequest request;
  request.output.width = request.output.height = 32;
  request.shadows.enabled = false;
  const auto result = gpu_test::renderer().render(request, renderer::kReadbackDisplay);
  EXPECT_FALSE(result.stats.passes[0].ran);
  EXPECT_EQ(result.display.pixels.size(), 32u * 32u * 4u);
}

TEST_F(EdgeScenes, ResolutionChangesBetweenRequestsReuseNothingStale) {
  api::RenderRequest request;
  auto render_at = [&](std::uint32_t width, std::uint32_t height) {
    request.output.width = width;
    request.output.height = height;
    return gpu_test::renderer().render(request).display;
  };
  const image::Rgba8Image first = render_at(64, 67);
  const image::Rgba8Image small = render_at(17, 20);  // the frame targets are rebuilt smaller ...
  EXPECT_EQ(small.pixels.size(), 17u * 20u * 4u);
  const image::Rgba8Image again = render_at(64, 67);  // ... and again at the first size
  EXPECT_EQ(again.pixels, first.pixels) << "a frame after a resize differs from the same frame before it";
}

}  // namespace
