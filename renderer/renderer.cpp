#include "renderer/renderer.hpp"

#include "api/counted.hpp"
#include "api/request_error.hpp"
#include "core/elapsed.hpp"
#include "renderer/frame_executor.hpp"
#include "renderer/frame_plan.hpp"
#include "renderer/frame_resources.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_readback.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/passes/lpv_gather_pass.hpp"
#include "renderer/scene_cache.hpp"
#include "scene/builtin_scenes.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

namespace renderer {
namespace {

using Clock = std::chrono::steady_clock;
using core::ms_since;

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
        executor(device, texture_layout, options.propagate_column),
        scene_source(std::move(options.scenes)),
        progress(std::move(options.progress)),
        scenes(options.scene_cache_bytes),
        test_slowdown(options.test_slowdown) {}

  const vkx::Device& device;
  TextureSetLayout texture_layout;
  FrameExecutor executor;  // the passes, run by plan

  SceneSource scene_source;
  std::function<void(const RenderProgress&)> progress;
  std::function<bool()> stop_check;
  SceneCache scenes;
  double test_slowdown;
  FrameResources resources;

  RenderResult render(const scene::Scene& scene, const GpuScene& gpu, const api::RenderRequest& request,
                      unsigned readback, double load_ms, double upload_ms);
  // The stats of a request before any frame is timed: what it renders, the plan, the
  // device, the warnings. A dry run returns them as they are.
  api::RenderStats plan_stats(const scene::Scene& scene, const api::RenderRequest& request, const FramePlan& plan,
                              double plan_ms) const;
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
  if (request.lpv.far_lines == api::FarLines::per_block && plan.run[kGather] && lpv_plan.setup.occlusion &&
      !LpvGatherPass::shares_far_lines(device.info())) {
    plan.decisions.push_back("lpv.far_lines per_cell: the device's subgroups of " +
                             std::to_string(device.info().subgroup_size) +
                             " lanes cannot share a 2x2x2 block's lines (per_block needs 8 or a multiple of 8)");
    request.lpv.far_lines = api::FarLines::per_cell;
  }
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

  RenderResult result;
  const FrameExecutor::Outcome ran = executor.run(
      {plan, gpu, request, light_setup, lpv_setup, iterations, resources, readback, gpu.camera_order(camera.position)},
      {stop_check, progress, test_slowdown}, result);
  const std::vector<std::uint32_t>& iterations_run = ran.iterations_run;

  for (std::uint32_t c = 0; c < iterations.size() && plan.run[kPropagate]; ++c)
    if (iterations_run[c] < iterations[c])
      plan.decisions.push_back("cascade " + std::to_string(c) + ": converged after " + std::to_string(iterations_run[c]) +
                               " of " + std::to_string(iterations[c]) +
                               " iterations (the steps left would add less than lpv.convergence of the light)");
  const std::uint32_t gathered = gathered_bounces(request.lpv.bounces).gathered;
  for (std::uint32_t c = 0; c < ran.bounces_run.size() && plan.run[kGather]; ++c)
    if (ran.bounces_run[c] < gathered)
      plan.decisions.push_back("cascade " + std::to_string(c) + ": the gather stopped after " +
                               std::to_string(ran.bounces_run[c]) + " of " + std::to_string(gathered) +
                               " bounces (the bounces left would add less than lpv.convergence of the light)");
  api::RenderStats& stats = result.stats;
  stats = plan_stats(scene, request, plan, plan_ms);
  stats.frames = request.repeat;
  ran.timings.summarize(stats);
  stats.cpu_ms["scene_load"] = api::TimeSummary::of({load_ms});
  stats.cpu_ms["scene_upload"] = api::TimeSummary::of({upload_ms});
  stats.cpu_ms["setup"] = api::TimeSummary::of({setup_ms});
  if (plan.run[kInject])
    stats.lpv = lpv_stats(*resources.volumes, request.lpv, lpv_setup, plan.run[kRsm], gpu.emitter_count, iterations_run,
                          plan.run[kGather] ? ran.bounces_run : std::vector<std::uint32_t>{});
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
  if (request.lpv.bounces > 1 && !request.lpv.occlusion && plan.run[kPropagate])
    stats.warnings.push_back("lpv.bounces > 1 needs occlusion: light is reflected where the geometry volume blocks it");
  return stats;
}


}  // namespace renderer
