#include "renderer/renderer.hpp"

#include "api/counted.hpp"
#include "api/request_error.hpp"
#include "renderer/frame_plan.hpp"
#include "renderer/frame_resources.hpp"
#include "renderer/frame_schedule.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_readback.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/pass_timer.hpp"
#include "renderer/passes/forward_pass.hpp"
#include "renderer/passes/gbuffer_pass.hpp"
#include "renderer/passes/geometry_volume_pass.hpp"
#include "renderer/passes/lpv_gather_pass.hpp"
#include "renderer/passes/lpv_inject_pass.hpp"
#include "renderer/passes/lpv_propagate_pass.hpp"
#include "renderer/passes/rsm_pass.hpp"
#include "renderer/passes/shade_pass.hpp"
#include "renderer/passes/shadow_pass.hpp"
#include "renderer/scene_cache.hpp"
#include "scene/builtin_scenes.hpp"
#include "vkx/command_buffer.hpp"
#include "vkx/vk_check.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

namespace renderer {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::uint32_t gpu_view(api::View v) {
  switch (v) {
    case api::View::final_: return gpu::VIEW_FINAL;
    case api::View::direct: return gpu::VIEW_DIRECT;
    case api::View::indirect: return gpu::VIEW_INDIRECT;
    case api::View::lpv: return gpu::VIEW_LPV;
    case api::View::albedo: return gpu::VIEW_ALBEDO;
    case api::View::normal: return gpu::VIEW_NORMAL;
    case api::View::depth: return gpu::VIEW_DEPTH;
  }
  return gpu::VIEW_FINAL;
}

// Keeps this thread busy, as work would, for `ms` (RendererOptions::test_slowdown).
void busy_wait_ms(double ms) {
  const auto until = Clock::now() + std::chrono::duration<double, std::milli>(ms);
  while (Clock::now() < until) {
  }
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

// Every pass with whether it runs and why, without times; a dry run's passes are only
// planned, none ran.
std::vector<api::PassStats> pass_list(const FramePlan& plan, bool dry_run) {
  std::vector<api::PassStats> passes;
  for (std::uint32_t p = 0; p < kPassCount; ++p)
    passes.push_back({kPassNames[p], plan.run[p], plan.run[p] && !dry_run, plan.reason[p], {}, {}});
  return passes;
}

}  // namespace

unsigned readback_for(const api::Output& output) {
  return output.format == api::ImageFormat::png ? kReadbackDisplay : kReadbackLinear;
}

struct Renderer::Impl {
  Impl(const vkx::Device& device, RendererOptions options)
      : device(device),
        texture_layout(device),
        shadow(device),
        rsm(device, texture_layout),
        gbuffer(device, texture_layout),
        forward(device, texture_layout),
        inject(device),
        geometry(device),
        propagate(device, options.propagate_column),
        gather(device),
        shade(device),
        timer(device),
        commands(device),
        scene_source(std::move(options.scenes)),
        progress(std::move(options.progress)),
        scenes(options.scene_cache_bytes),
        test_slowdown(options.test_slowdown) {}

  const vkx::Device& device;
  TextureSetLayout texture_layout;
  ShadowPass shadow;
  RsmPass rsm;
  GBufferPass gbuffer;
  ForwardPass forward;
  LpvInjectPass inject;
  GeometryVolumePass geometry;
  LpvPropagatePass propagate;
  LpvGatherPass gather;
  ShadePass shade;
  PassTimer timer;
  vkx::ReusableCommandBuffer commands;

  SceneSource scene_source;
  std::function<void(const RenderProgress&)> progress;
  std::function<bool()> stop_check;
  SceneCache scenes;
  double test_slowdown;
  FrameResources resources;

  // What the passes of one frame read, fixed before the first is recorded.
  struct Frame {
    const FramePlan& plan;
    const GpuScene& gpu;
    const api::RenderRequest& request;
    const LightSetup& lights;
    const LpvSetup& lpv;
    unsigned readback;
    std::vector<std::uint32_t> draw_order;  // of the camera's raster passes (GpuScene::camera_order)
  };

  RenderResult render(const scene::Scene& scene, const GpuScene& gpu, const api::RenderRequest& request,
                      unsigned readback, double load_ms, double upload_ms);
  // The stats of a request before any frame is timed: what it renders, the plan, the
  // device, the warnings. A dry run returns them as they are.
  api::RenderStats plan_stats(const scene::Scene& scene, const api::RenderRequest& request, const FramePlan& plan,
                              double plan_ms) const;
  // Steps first .. first + count - 1 of propagation (1-based), or slabs first - 1 ..
  // first + count - 2 of the gather; other passes ignore them.
  struct Steps {
    std::uint32_t first = 1;
    std::uint32_t count = 0;
  };
  void record_pass(Pass pass, std::uint32_t cascade, Steps steps, const Frame& frame);
  // What the forward pass and the shading read of the lights. Views without direct light never
  // read them: no kinds and count 0, so one shading pipeline serves every light setup.
  DirectLightInputs direct_light(const Frame& frame) const {
    const bool lit = needs_direct_light(frame.request.output.view);
    return {resources.frame_uniforms,
            resources.light_buffer,
            resources.shadow_view_buffer,
            *resources.atlas,
            lit ? light_kinds(frame.lights.lights, frame.gpu.emissive) : 0u,
            lit ? std::uint32_t(frame.lights.lights.size()) : 0u};
  }
  // What the forward pass and the shading read of the LPV: its cascades when it ran, else none.
  IndirectLightInputs indirect_light(const Frame& frame) const {
    return {resources.lpv_uniforms, *resources.volumes, frame.plan.run[kInject] ? std::uint32_t(frame.lpv.cascades.size()) : 0u};
  }
  // The named scene, made resident (loaded, uploaded and warmed up) if it is not; the times
  // are 0 when it was.
  struct Residency {
    const ResidentScene& scene;
    double load_ms = 0.0, upload_ms = 0.0, warm_up_ms = 0.0;
  };
  Residency resident(const std::string& name);
  // Small frames of a newly resident scene through both shading paths (forward to the
  // display image; G-buffer and shade to linear images), indirect light included: lavapipe
  // makes a material's pipeline on first use and compiles texture-sampling code at the first
  // draw that binds a new texture, 50-250 ms the first frame would otherwise pay.
  void warm_up(const ResidentScene& scene);
};

Renderer::Renderer(const vkx::Device& device, RendererOptions options)
    : device_(device), impl_(std::make_unique<Impl>(device, std::move(options))) {}
Renderer::~Renderer() = default;

Renderer::Impl::Residency Renderer::Impl::resident(const std::string& name) {
  if (const ResidentScene* resident = scenes.find(name)) return {*resident};
  const auto load_start = Clock::now();
  std::optional<scene::Scene> loaded = scene::make_builtin_scene(name);
  if (!loaded && scene_source) loaded = scene_source(name);
  if (!loaded) {
    std::string names;
    for (const auto& info : scene::builtin_scenes()) names += (names.empty() ? "" : ", ") + info.name;
    throw api::NotFound("scene", "unknown scene '" + name + "'; built-in scenes: " + names);
  }
  const double load_ms = ms_since(load_start);
  const auto upload_start = Clock::now();
  GpuScene gpu = GpuScene::upload(device, *loaded, texture_layout);
  const double upload_ms = ms_since(upload_start);
  const std::uint64_t bytes = loaded->memory_bytes() + gpu.bytes();
  const ResidentScene& scene = scenes.insert({name, std::move(*loaded), std::move(gpu), bytes});
  const auto warm_start = Clock::now();
  warm_up(scene);
  return {scene, load_ms, upload_ms, ms_since(warm_start)};
}

void Renderer::Impl::warm_up(const ResidentScene& scene) {
  api::RenderRequest request;
  request.scene = scene.name;
  request.output.width = request.output.height = 32;
  // The warm-up's frames are not the request's: no progress is reported for them.
  const auto quiet = std::exchange(progress, nullptr);
  try {
    for (const unsigned readback : {kReadbackDisplay, kReadbackLinear})
      (void)render(scene.scene, scene.gpu, request, readback, 0.0, 0.0);
  } catch (const api::RequestError&) {
    // A scene the default request does not fit: the request at hand says why, if it fails too.
  } catch (...) {
    progress = quiet;
    throw;
  }
  progress = quiet;
}

RenderResult Renderer::render(const api::RenderRequest& request, unsigned readback) {
  const Impl::Residency scene = impl_->resident(request.scene);
  RenderResult result = impl_->render(scene.scene.scene, scene.scene.gpu, request, readback, scene.load_ms, scene.upload_ms);
  if (scene.warm_up_ms > 0.0) result.stats.cpu_ms["warm_up"] = api::TimeSummary::of({scene.warm_up_ms});
  return result;
}

double Renderer::prepare(const std::string& name) { return impl_->resident(name).warm_up_ms; }

const scene::Scene& Renderer::scene(const std::string& name) { return impl_->resident(name).scene.scene; }

RenderResult Renderer::render(const scene::Scene& scene, const api::RenderRequest& request, unsigned readback) {
  const auto start = Clock::now();
  GpuScene gpu = GpuScene::upload(device_, scene, impl_->texture_layout);
  return impl_->render(scene, gpu, request, readback, 0.0, ms_since(start));
}

void Renderer::forget_scene(const std::string& name) { impl_->scenes.erase(name); }

void Renderer::set_stop_check(std::function<bool()> stop) { impl_->stop_check = std::move(stop); }

SceneCacheStats Renderer::scene_cache() const { return {impl_->scenes.size(), impl_->scenes.bytes()}; }

RenderResult Renderer::Impl::render(const scene::Scene& scene, const GpuScene& gpu, const api::RenderRequest& asked,
                                    unsigned readback, double load_ms, double upload_ms) {
  const auto setup_start = Clock::now();
  api::RenderRequest request = asked;  // as the plan changes it
  // Requests and sweeps are checked when read; a request built in code is checked here, on the
  // grid asked for (the plan may arrange the gather's cells differently, never more of them).
  if (const std::string problem = api::gather_grid_problem(request.lpv.grid, request.lpv.transfer); !problem.empty())
    throw api::DoesNotFit("lpv.grid", problem);
  request.lpv.transfer = api::resolved_transfer(request.lpv.grid, request.lpv.transfer);
  const api::Output& out = request.output;
  const std::vector<api::Light> lights = resolve_lights(scene, request);
  const api::Camera camera_request = request.camera.value_or(scene.camera);
  const CameraSetup camera = setup_camera(camera_request, scene.bounds, float(out.width) / float(out.height));
  auto plan_start = Clock::now();
  FramePlan plan =
      plan_frame({request, lights, scene, gpu.emitter_count, camera.view_proj});
  if (asked.lpv.transfer == api::Transfer::auto_ && plan.run[kInject])
    plan.decisions.push_back(transfer_choice(request.lpv));
  std::vector<LightView> views = light_views(lights, scene.bounds, plan.light_drawn);
  request.shadows.resolution = plan_shadow_resolution(plan, request, scene, lights, views, camera,
                                                      camera_request.fov_y_deg, kShadowAtlasBudgetBytes / 4);
  double plan_ms = ms_since(plan_start);
  const LightSetup light_setup = setup_lights(lights, std::move(views), request.shadows, plan.light_shadowed);
  plan_start = Clock::now();
  const LpvPlan lpv_plan = plan_lpv(
      plan, request, scene,
      {lights, light_setup.views, gpu.emitted_flux, camera, camera_request.fov_y_deg, out.height});
  request.lpv = lpv_plan.settings;
  plan_shading(plan, request.output.view, readback == kReadbackDisplay);
  if (plan.run[kGeometryVolume]) {  // why it runs: what it is made of
    plan.reason[kGeometryVolume] = describe_occluders(geometry_sources(request.lpv, plan.run[kRsm]), gpu.blocker_count);
  }
  plan_ms += ms_since(plan_start);
  const LpvSetup& lpv_setup = lpv_plan.setup;
  const std::vector<std::uint32_t>& iterations = lpv_plan.iterations;
  if (request.dry_run) {
    RenderResult planned;
    planned.stats = plan_stats(scene, request, plan, plan_ms);
    return planned;
  }
  resources.fit(device, plan, request, light_setup);

  gpu::GpuFrame frame{};
  frame.view_proj = camera.view_proj;
  frame.camera_position = glm::vec4(camera.position, 1.0f);
  frame.camera_forward = glm::vec4(camera.forward, 0.0f);
  frame.depth_range = glm::vec4(camera.near, camera.far, 0.0f, 0.0f);
  frame.exposure = glm::vec4(std::exp2(out.exposure), 0.0f, 0.0f, 0.0f);
  frame.size_view = glm::uvec4(out.width, out.height, 0u, std::uint32_t(light_setup.lights.size()));
  resources.upload(device, frame, light_setup, lpv_setup);
  const double setup_ms = ms_since(setup_start);

  const Frame context{plan, gpu, request, light_setup, lpv_setup, readback, gpu.camera_order(camera.position)};
  const auto cascades = std::uint32_t(lpv_setup.cascades.size());
  const std::vector<ScheduledPass> schedule = pass_schedule(plan, cascades);
  RenderResult result;
  FrameTimings timings(cascades);
  std::vector<std::uint32_t> iterations_run(iterations.size(), 0);
  std::size_t passes_done = 0;  // for progress reports
  for (std::uint32_t f = 0; f < request.repeat; ++f) {
    const auto frame_start = Clock::now();
    FrameTime frame_time;
    for (const auto& [p, c] : schedule) {
      // Propagation that may stop early runs in chunks, the flux of each chunk's last step
      // read in between; the gather, one slab of cells at a time when it may be stopped;
      // every other pass is one submission.
      // A stop check is asked between chunks too. The chunks' results are the same bits as one
      // submission's: the same dispatches in the same order.
      const std::uint32_t steps = p == kPropagate ? iterations[c] : p == kGather ? LpvGatherPass::slabs(*resources.volumes) : 1;
      const bool chunked = (p == kPropagate && (plan.convergence > 0.0f || stop_check)) || (p == kGather && stop_check);
      const std::uint32_t chunk = !chunked ? steps : p == kGather ? 1 : kConvergenceChunk;
      double pass_gpu_ms = 0.0;
      std::uint32_t done = 0;
      while (done < steps) {
        if (stop_check && stop_check()) throw RenderStopped();
        const std::uint32_t n = std::min(chunk, steps - done);
        const auto record_start = Clock::now();
        record_pass(p, c, {done + 1, n}, context);
        frame_time.record_ms += ms_since(record_start);
        const auto submit_start = Clock::now();
        device.submit_and_wait(commands.handle());
        const double waited = ms_since(submit_start);
        frame_time.wait_ms += waited;
        pass_gpu_ms += timer.device_ms(waited);
        done += n;
        if (p == kPropagate && done < steps && plan.convergence > 0.0f &&
            propagation_converged(*resources.volumes, c, done, steps, plan.convergence))
          break;
      }
      if (p == kPropagate) iterations_run[c] = done;
      if (is_grid_pass(p)) timings.add_cascade(p, c, pass_gpu_ms);
      frame_time.pass_ms[p] += pass_gpu_ms;
      frame_time.gpu_ms += pass_gpu_ms;
      if (progress)
        progress({f + 1, request.repeat, kPassNames[p], double(++passes_done) / double(schedule.size() * request.repeat)});
    }
    const auto readback_start = Clock::now();
    if (readback & kReadbackDisplay) copy_to_host(resources.targets->display_readback, out, result.display);
    if (readback & kReadbackLinear) copy_to_host(resources.targets->linear_readback, out, result.linear);
    const double readback_ms = ms_since(readback_start);
    if (test_slowdown > 1.0) busy_wait_ms(ms_since(frame_start) * (test_slowdown - 1.0));
    timings.add_frame(plan, frame_time, readback_ms, ms_since(frame_start));
  }

  for (std::uint32_t c = 0; c < iterations.size() && plan.run[kPropagate]; ++c)
    if (iterations_run[c] < iterations[c])
      plan.decisions.push_back("cascade " + std::to_string(c) + ": converged after " + std::to_string(iterations_run[c]) +
                               " of " + std::to_string(iterations[c]) +
                               " iterations (the steps left would add less than lpv.convergence of the light)");
  api::RenderStats& stats = result.stats;
  stats = plan_stats(scene, request, plan, plan_ms);
  stats.frames = request.repeat;
  timings.summarize(stats);
  stats.cpu_ms["scene_load"] = api::TimeSummary::of({load_ms});
  stats.cpu_ms["scene_upload"] = api::TimeSummary::of({upload_ms});
  stats.cpu_ms["setup"] = api::TimeSummary::of({setup_ms});
  if (plan.run[kInject])
    stats.lpv = lpv_stats(*resources.volumes, request.lpv, lpv_setup, plan.run[kRsm], gpu.emitter_count, iterations_run);
  if (plan.run[kInject] && (readback & kReadbackLpv))
    result.lpv = lpv_snapshot(device, *resources.rsm_maps, *resources.volumes, lpv_setup, plan.run[kGeometryVolume]);
  return result;
}

api::RenderStats Renderer::Impl::plan_stats(const scene::Scene& scene, const api::RenderRequest& request,
                                            const FramePlan& plan, double plan_ms) const {
  api::RenderStats stats;
  stats.scene = scene.name;
  stats.width = request.output.width;
  stats.height = request.output.height;
  stats.view = api::to_string(request.output.view);
  stats.plan = api::to_string(request.plan);
  stats.decisions = plan.decisions;
  stats.passes = pass_list(plan, request.dry_run);
  stats.cpu_ms["plan"] = api::TimeSummary::of({plan_ms});
  stats.device = device.info().name;
  stats.driver = device.info().driver;
  stats.warnings = scene.warnings;
  if (request.lpv.intensity != 1.0f && needs_indirect_light(request.output.view))
    stats.warnings.push_back("lpv.intensity is " + std::to_string(request.lpv.intensity) +
                             ": the indirect light is scaled and no longer physically based");
  if (request.lpv.bounces > 1 && !request.lpv.occlusion && plan.run[kInject])
    stats.warnings.push_back("lpv.bounces > 1 needs occlusion: light is reflected where the geometry volume blocks it");
  return stats;
}


// Records one pass (for the grid passes: one cascade of it), bracketed by the pass timer.
void Renderer::Impl::record_pass(Pass pass, std::uint32_t cascade, Steps steps, const Frame& frame) {
  const VkCommandBuffer cmd = commands.begin();
  const api::Lpv& lpv = frame.request.lpv;
  timer.begin(cmd);
  // The camera's raster pass (G-buffer or forward) is the first to bind the shadow resources.atlas: it
  // needs its layout even when no map was drawn (no light samples it then).
  if ((pass == kGBuffer || pass == kForward) && !frame.plan.run[kShadow]) ShadowPass::record_skipped(cmd, *resources.atlas);
  switch (pass) {
    case kShadow:
      shadow.record(cmd, frame.gpu, *resources.atlas, frame.lights.shadow_views);
      break;
    case kRsm:
      rsm.record(cmd, frame.gpu, *resources.rsm_maps, resources.rsm_view_buffer, resources.light_buffer);
      break;
    case kGBuffer:
      gbuffer.record(cmd, frame.gpu, frame.draw_order, resources.targets->camera, resources.frame_uniforms);
      break;
    case kInject:
      if (cascade == 0 && !frame.plan.run[kRsm]) RsmPass::record_skipped(cmd, *resources.rsm_maps);
      inject.record(cmd, cascade, resources.lpv_uniforms, frame.plan.run[kRsm] ? &*resources.rsm_maps : nullptr, vpls_per_view_side(lpv),
                    frame.gpu, *resources.volumes, lpv.injection);
      break;
    case kGeometryVolume: {
      if (cascade == 0) {  // the camera's surfels, drawn once for every cascade (timed with the first)
        if (lpv.occlusion_from_camera)
          gbuffer.record(cmd, frame.gpu, frame.draw_order, resources.targets->surfels, resources.frame_uniforms);
        else
          GBufferPass::record_unused(cmd, resources.targets->surfels);
      }
      GeometrySources sources = geometry_sources(lpv, frame.plan.run[kRsm]);
      sources.rsm_stride = frame.lpv.gpu.sizes.w;
      sources.bounces = frame.lpv.bounces;
      geometry.record(cmd, cascade, resources.lpv_uniforms, *resources.rsm_maps, resources.targets->surfels, frame.gpu, sources, *resources.volumes);
      break;
    }
    case kPropagate:
      propagate.record(cmd, cascade, steps.first, steps.count, frame.lpv.occlusion, frame.lpv.bounces, resources.lpv_uniforms,
                       *resources.volumes);
      break;
    case kGather:
      gather.record(cmd, cascade, steps.first - 1, steps.count, frame.lpv.occlusion, resources.lpv_uniforms,
                    *resources.volumes);
      break;
    case kForward:
      forward.record(cmd, frame.gpu, frame.draw_order, *resources.targets, direct_light(frame), indirect_light(frame),
                     frame.request.output.tonemap);
      break;
    case kShade:
      shade.record(cmd, frame.gpu, *resources.targets,
                   {direct_light(frame), indirect_light(frame), gpu_view(frame.request.output.view),
                    (frame.readback & kReadbackLinear ? gpu::SHADE_OUTPUT_LINEAR : 0u) |
                        (frame.readback & kReadbackDisplay ? gpu::SHADE_OUTPUT_DISPLAY : 0u),
                    frame.request.output.tonemap});
      break;
    case kReadback: {
      auto copy = [&](const vkx::Buffer& from, const vkx::Buffer& to) {
        const VkBufferCopy region{0, 0, from.size()};
        vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
      };
      if (frame.readback & kReadbackDisplay) copy(resources.targets->display, resources.targets->display_readback);
      if (frame.readback & kReadbackLinear) copy(resources.targets->linear, resources.targets->linear_readback);
      vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
      break;
    }
    case kPassCount:
      break;
  }
  timer.end(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
}

}  // namespace renderer
