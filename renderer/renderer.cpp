#include "renderer/renderer.hpp"

#include "api/request_error.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/pass_timer.hpp"
#include "renderer/passes/gbuffer_pass.hpp"
#include "renderer/passes/shade_pass.hpp"
#include "renderer/passes/shadow_pass.hpp"
#include "renderer/passes/tonemap_pass.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/vulkan/vk_check.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

namespace renderer {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Passes in recording and submission order.
enum Pass : std::uint32_t { kShadow, kGBuffer, kShade, kTonemap, kReadback, kPassCount };
constexpr const char* kPassNames[kPassCount] = {"shadow", "gbuffer", "shade", "tonemap", "readback"};

// Shadow maps live in host memory on lavapipe: bound them so a request cannot exhaust it.
constexpr std::uint64_t kShadowAtlasBudgetBytes = 1ull << 30;

bool is_lit_view(api::View v) { return v == api::View::final_ || v == api::View::direct; }

std::uint32_t gpu_view(api::View v) {
  switch (v) {
    case api::View::final_: return gpu::VIEW_FINAL;
    case api::View::direct: return gpu::VIEW_DIRECT;
    case api::View::albedo: return gpu::VIEW_ALBEDO;
    case api::View::normal: return gpu::VIEW_NORMAL;
    case api::View::depth: return gpu::VIEW_DEPTH;
  }
  return gpu::VIEW_FINAL;
}

// What one request runs, decided before anything is recorded.
struct FramePlan {
  bool run[kPassCount] = {};
  std::string reason[kPassCount];
};

FramePlan plan_frame(const api::RenderRequest& request, const LightSetup& lights, unsigned readback) {
  FramePlan plan;
  plan.run[kGBuffer] = plan.run[kShade] = plan.run[kReadback] = true;
  plan.run[kTonemap] = (readback & kReadbackDisplay) != 0;
  if (!plan.run[kTonemap]) plan.reason[kTonemap] = "no 8-bit image requested";
  if (!is_lit_view(request.output.view))
    plan.reason[kShadow] = "view '" + api::to_string(request.output.view) + "' needs no lighting";
  else if (!request.shadows.enabled)
    plan.reason[kShadow] = "shadows disabled";
  else if (lights.shadow_views.empty())
    plan.reason[kShadow] = "no light emits";
  plan.run[kShadow] = plan.reason[kShadow].empty();
  return plan;
}

// An RGBA image of the output's size from a mapped readback buffer.
template <typename Image>
void copy_to_host(const vkx::Buffer& readback, const api::Output& out, Image& image) {
  readback.invalidate();
  image.width = out.width;
  image.height = out.height;
  image.pixels.resize(std::size_t(out.width) * out.height * 4);
  std::memcpy(image.pixels.data(), readback.mapped(), image.pixels.size() * sizeof(image.pixels[0]));
}

void ensure_upload_capacity(const vkx::Device& device, vkx::Buffer& buffer, VkDeviceSize bytes,
                            VkBufferUsageFlags usage) {
  bytes = std::max<VkDeviceSize>(bytes, 256);  // never zero-sized, even with no lights
  if (!buffer || buffer.size() < bytes) buffer = vkx::Buffer(device, bytes, usage, vkx::MemoryUse::upload);
}

}  // namespace

unsigned readback_for(const api::Output& output) {
  return output.format == api::ImageFormat::png ? kReadbackDisplay : kReadbackLinear;
}

struct Renderer::Impl {
  explicit Impl(const vkx::Device& device)
      : device(device), shadow(device), gbuffer(device), shade(device), tonemap(device), timer(device) {
    VkCommandPoolCreateInfo pool_ci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_ci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_ci.queueFamilyIndex = device.queue_family();
    VK_CHECK(vkCreateCommandPool(device.handle(), &pool_ci, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device.handle(), &alloc, &commands));
  }
  ~Impl() { vkDestroyCommandPool(device.handle(), pool, nullptr); }

  const vkx::Device& device;
  ShadowPass shadow;
  GBufferPass gbuffer;
  ShadePass shade;
  TonemapPass tonemap;
  PassTimer timer;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer commands = VK_NULL_HANDLE;

  struct ResidentScene {
    scene::Scene scene;
    GpuScene gpu;
  };
  std::map<std::string, ResidentScene> builtin_scenes;  // uploaded on first use
  std::optional<FrameTargets> targets;
  std::optional<ShadowAtlas> atlas;
  vkx::Buffer frame_uniforms, light_buffer, shadow_view_buffer;

  RenderResult render(const scene::Scene& scene, const GpuScene& gpu, const api::RenderRequest& request,
                      unsigned readback, double upload_ms);
  void record_pass(Pass pass, const FramePlan& plan, const GpuScene& gpu, const api::RenderRequest& request,
                   std::span<const glm::mat4> shadow_views, unsigned readback);
};

Renderer::Renderer(const vkx::Device& device) : device_(device), impl_(std::make_unique<Impl>(device)) {}
Renderer::~Renderer() = default;

RenderResult Renderer::render(const api::RenderRequest& request, unsigned readback) {
  auto it = impl_->builtin_scenes.find(request.scene);
  double upload_ms = 0.0;
  if (it == impl_->builtin_scenes.end()) {
    std::optional<scene::Scene> made = scene::make_builtin_scene(request.scene);
    if (!made) {
      std::string names;
      for (const auto& info : scene::builtin_scenes()) names += (names.empty() ? "" : ", ") + info.name;
      throw api::RequestError("scene", "unknown scene '" + request.scene + "'; built-in scenes: " + names);
    }
    const auto start = Clock::now();
    GpuScene gpu = GpuScene::upload(device_, *made);
    upload_ms = ms_since(start);
    it = impl_->builtin_scenes.emplace(request.scene, Impl::ResidentScene{std::move(*made), std::move(gpu)}).first;
  }
  return impl_->render(it->second.scene, it->second.gpu, request, readback, upload_ms);
}

RenderResult Renderer::render(const scene::Scene& scene, const api::RenderRequest& request, unsigned readback) {
  const auto start = Clock::now();
  GpuScene gpu = GpuScene::upload(device_, scene);
  return impl_->render(scene, gpu, request, readback, ms_since(start));
}

RenderResult Renderer::Impl::render(const scene::Scene& scene, const GpuScene& gpu, const api::RenderRequest& request,
                                    unsigned readback, double upload_ms) {
  const auto setup_start = Clock::now();
  const api::Output& out = request.output;
  const std::vector<api::Light> lights = resolve_lights(scene, request);
  const CameraSetup camera =
      setup_camera(request.camera.value_or(scene.camera), scene.bounds, float(out.width) / float(out.height));
  const LightSetup light_setup = setup_lights(lights, scene.bounds, request.shadows);
  const FramePlan plan = plan_frame(request, light_setup, readback);

  const std::uint32_t layers = std::max<std::uint32_t>(1, std::uint32_t(light_setup.shadow_views.size()));
  const std::uint32_t resolution = plan.run[kShadow] ? request.shadows.resolution : 1;
  const std::uint64_t atlas_bytes = std::uint64_t(resolution) * resolution * layers * 4;
  if (atlas_bytes > kShadowAtlasBudgetBytes)
    throw api::RequestError("shadows.resolution",
                            std::to_string(layers) + " shadow maps of " + std::to_string(resolution) + "^2 need " +
                                std::to_string(atlas_bytes >> 20) + " MiB, over the budget of " +
                                std::to_string(kShadowAtlasBudgetBytes >> 20) + " MiB: lower the resolution");

  if (!targets || targets->width != out.width || targets->height != out.height) {
    targets.reset();  // free the old ones before allocating the new
    targets.emplace(device, out.width, out.height);
  }
  if (!atlas || atlas->resolution != resolution || atlas->layers != layers) {
    atlas.reset();
    atlas.emplace(device, resolution, layers);
  }

  gpu::GpuFrame frame{};
  frame.view_proj = camera.view_proj;
  frame.camera_position = glm::vec4(camera.position, 1.0f);
  frame.camera_forward = glm::vec4(camera.forward, 0.0f);
  frame.depth_range = glm::vec4(camera.near, camera.far, 0.0f, 0.0f);
  frame.exposure = glm::vec4(std::exp2(out.exposure), 0.0f, 0.0f, 0.0f);
  frame.size_view = glm::uvec4(out.width, out.height, gpu_view(out.view), std::uint32_t(light_setup.lights.size()));
  const auto light_bytes = light_setup.lights.size() * sizeof(gpu::GpuLight);
  const auto view_bytes = light_setup.shadow_views.size() * sizeof(glm::mat4);
  ensure_upload_capacity(device, frame_uniforms, sizeof(frame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  ensure_upload_capacity(device, light_buffer, light_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ensure_upload_capacity(device, shadow_view_buffer, view_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  frame_uniforms.write(&frame, sizeof(frame));
  if (light_bytes) light_buffer.write(light_setup.lights.data(), light_bytes);
  if (view_bytes) shadow_view_buffer.write(light_setup.shadow_views.data(), view_bytes);
  const double setup_ms = ms_since(setup_start);

  RenderResult result;
  std::vector<double> record_ms, wait_ms, readback_ms, wall_ms, total_gpu_ms;
  std::vector<std::vector<double>> pass_ms(kPassCount);
  for (std::uint32_t f = 0; f < request.repeat; ++f) {
    const auto frame_start = Clock::now();
    double frame_record_ms = 0.0, frame_wait_ms = 0.0, frame_gpu_ms = 0.0;
    for (std::uint32_t p = 0; p < kPassCount; ++p) {
      if (!plan.run[p]) continue;
      const auto record_start = Clock::now();
      record_pass(Pass(p), plan, gpu, request, light_setup.shadow_views, readback);
      frame_record_ms += ms_since(record_start);
      const auto submit_start = Clock::now();
      device.submit_and_wait(commands);
      const double waited = ms_since(submit_start);
      frame_wait_ms += waited;
      pass_ms[p].push_back(timer.device_ms(waited));
      frame_gpu_ms += pass_ms[p].back();
    }
    record_ms.push_back(frame_record_ms);
    wait_ms.push_back(frame_wait_ms);
    total_gpu_ms.push_back(frame_gpu_ms);

    const auto readback_start = Clock::now();
    if (readback & kReadbackDisplay) copy_to_host(targets->display_readback, out, result.display);
    if (readback & kReadbackLinear) copy_to_host(targets->linear_readback, out, result.linear);
    readback_ms.push_back(ms_since(readback_start));
    wall_ms.push_back(ms_since(frame_start));
  }

  api::RenderStats& stats = result.stats;
  stats.scene = scene.name;
  stats.width = out.width;
  stats.height = out.height;
  stats.view = api::to_string(out.view);
  stats.frames = request.repeat;
  for (std::uint32_t p = 0; p < kPassCount; ++p) {
    api::PassStats ps;
    ps.name = kPassNames[p];
    ps.ran = plan.run[p];
    ps.reason = plan.reason[p];
    if (ps.ran) ps.gpu_ms = api::TimeSummary::of(pass_ms[p]);
    stats.passes.push_back(std::move(ps));
  }
  stats.gpu_ms = api::TimeSummary::of(total_gpu_ms);
  stats.cpu_ms["scene_upload"] = api::TimeSummary::of({upload_ms});
  stats.cpu_ms["setup"] = api::TimeSummary::of({setup_ms});
  stats.cpu_ms["record"] = api::TimeSummary::of(record_ms);
  stats.cpu_ms["submit_wait"] = api::TimeSummary::of(wait_ms);
  stats.cpu_ms["readback"] = api::TimeSummary::of(readback_ms);
  stats.wall_ms = api::TimeSummary::of(wall_ms);
  stats.device = device.info().name;
  stats.driver = device.info().driver;
  return result;
}

// Records one pass into the command buffer, bracketed by the pass timer.
void Renderer::Impl::record_pass(Pass pass, const FramePlan& plan, const GpuScene& gpu, const api::RenderRequest& request,
                                 std::span<const glm::mat4> shadow_views, unsigned readback) {
  VK_CHECK(vkResetCommandBuffer(commands, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(commands, &begin));
  VkCommandBuffer cmd = commands;
  timer.begin(cmd);
  switch (pass) {
    case kShadow:
      shadow.record(cmd, gpu, *atlas, shadow_views);
      break;
    case kGBuffer:
      // The shading binds the atlas even when no map was drawn (no light samples it then).
      if (!plan.run[kShadow]) ShadowPass::record_skipped(cmd, *atlas);
      gbuffer.record(cmd, gpu, *targets, frame_uniforms);
      break;
    case kShade:
      shade.record(cmd, gpu, *targets, {frame_uniforms, light_buffer, shadow_view_buffer, *atlas});
      break;
    case kTonemap:
      tonemap.record(cmd, *targets, request.output.tonemap,
                     request.output.view != api::View::normal && request.output.view != api::View::depth);
      break;
    case kReadback: {
      auto copy = [&](const vkx::Buffer& from, const vkx::Buffer& to) {
        const VkBufferCopy region{0, 0, from.size()};
        vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
      };
      if (readback & kReadbackDisplay) copy(targets->display, targets->display_readback);
      if (readback & kReadbackLinear) copy(targets->linear, targets->linear_readback);
      vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
      break;
    }
    case kPassCount:
      break;
  }
  timer.end(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
}

}  // namespace renderer
