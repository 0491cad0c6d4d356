#include "renderer/frame_executor.hpp"

#include "core/elapsed.hpp"
#include "renderer/lpv/lpv_readback.hpp"
#include "vkx/vk_check.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace renderer {
namespace {

using Clock = std::chrono::steady_clock;
using core::ms_since;

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

}  // namespace

FrameExecutor::FrameExecutor(const vkx::Device& device, const TextureSetLayout& textures,
                             std::uint32_t propagate_column)
    : device_(device),
      shadow_(device),
      rsm_(device, textures),
      gbuffer_(device, textures),
      forward_(device, textures),
      inject_(device),
      geometry_(device),
      propagate_(device, propagate_column),
      gather_(device),
      shade_(device),
      timer_(device),
      commands_(device) {}

FrameExecutor::Outcome FrameExecutor::run(const Frame& frame, const Controls& controls, RenderResult& result) {
  const FramePlan& plan = frame.plan;
  const std::uint32_t repeat = frame.request.repeat;
  const auto cascades = std::uint32_t(frame.lpv.cascades.size());
  const std::vector<ScheduledPass> schedule = pass_schedule(plan, cascades);
  Outcome outcome{FrameTimings(cascades), std::vector<std::uint32_t>(frame.iterations.size(), 0),
                  std::vector<std::uint32_t>(cascades, 0)};
  std::size_t passes_done = 0;  // for progress reports
  for (std::uint32_t f = 0; f < repeat; ++f) {
    const auto frame_start = Clock::now();
    FrameTime frame_time;
    for (const auto& [p, c] : schedule) {
      // Propagation that may stop early runs in chunks, the flux of each chunk's last step
      // read in between; the gather, one slab of cells at a time when it may be stopped;
      // every other pass is one submission.
      // A stop check is asked between chunks too. The chunks' results are the same bits as one
      // submission's: the same dispatches in the same order.
      // The gather's bounces, one submission each when it may stop once the light left is
      // small (as propagation's steps: lpv.convergence), its slabs one each when it may be stopped.
      const GatheredBounces bounces = gathered_bounces(frame.request.lpv.bounces);
      const std::uint32_t slabs = LpvGatherPass::slabs(*frame.resources.volumes);
      const bool bounces_converge = plan.convergence > 0.0f && bounces.gathered > 1 && !bounces.tail;
      const std::uint32_t steps =
          p == kPropagate ? frame.iterations[c] : p == kGather ? slabs * bounces.gathered : 1;
      const bool stoppable = bool(controls.stop_check);
      const bool chunked = (p == kPropagate && (plan.convergence > 0.0f || stoppable)) ||
                           (p == kGather && (stoppable || bounces_converge));
      const std::uint32_t chunk = !chunked ? steps : p == kGather ? (stoppable ? 1 : slabs) : kConvergenceChunk;
      double pass_gpu_ms = 0.0;
      std::uint32_t done = 0;
      while (done < steps) {
        if (stoppable && controls.stop_check()) throw RenderStopped();
        const std::uint32_t n = std::min(chunk, steps - done);
        const auto record_start = Clock::now();
        record_pass(p, c, {done + 1, n}, frame);
        frame_time.record_ms += ms_since(record_start);
        const auto submit_start = Clock::now();
        device_.submit_and_wait(commands_.handle());
        const double waited = ms_since(submit_start);
        frame_time.wait_ms += waited;
        pass_gpu_ms += timer_.device_ms(waited);
        done += n;
        if (p == kPropagate && done < steps && plan.convergence > 0.0f &&
            propagation_converged(*frame.resources.volumes, c, done, steps, plan.convergence))
          break;
        if (p == kGather && bounces_converge && done < steps && done % slabs == 0 &&
            gather_converged(*frame.resources.volumes, c, done / slabs, bounces.gathered, plan.convergence))
          break;
      }
      if (p == kPropagate) outcome.iterations_run[c] = done;
      if (p == kGather) outcome.bounces_run[c] = done / slabs;
      if (is_grid_pass(p)) outcome.timings.add_cascade(p, c, pass_gpu_ms);
      frame_time.pass_ms[p] += pass_gpu_ms;
      frame_time.gpu_ms += pass_gpu_ms;
      if (controls.progress)
        controls.progress({f + 1, repeat, kPassNames[p], double(++passes_done) / double(schedule.size() * repeat)});
    }
    const auto readback_start = Clock::now();
    const api::Output& out = frame.request.output;
    if (frame.readback & kReadbackDisplay) copy_to_host(frame.resources.targets->display_readback, out, result.display);
    if (frame.readback & kReadbackLinear) copy_to_host(frame.resources.targets->linear_readback, out, result.linear);
    const double readback_ms = ms_since(readback_start);
    if (controls.test_slowdown > 1.0) busy_wait_ms(ms_since(frame_start) * (controls.test_slowdown - 1.0));
    outcome.timings.add_frame(plan, frame_time, readback_ms, ms_since(frame_start));
  }
  return outcome;
}

// What the forward pass and the shading read of the lights. Views without direct light never
// read them: no kinds and count 0, so one shading pipeline serves every light setup.
DirectLightInputs FrameExecutor::direct_light(const Frame& frame) const {
  const bool lit = needs_direct_light(frame.request.output.view);
  return {frame.resources.frame_uniforms,
          frame.resources.light_buffer,
          frame.resources.shadow_view_buffer,
          *frame.resources.atlas,
          lit ? light_kinds(frame.lights.lights, frame.gpu.emissive) : 0u,
          lit ? std::uint32_t(frame.lights.lights.size()) : 0u};
}

// Whether the geometry volume locates its walls for the injection and the shading
// (lpv.line_blocking "located", wherever blockers are built: propagation's light too).
bool FrameExecutor::walls_located(const Frame& frame) {
  return frame.plan.run[kGeometryVolume] && frame.lpv.occlusion &&
         frame.request.lpv.line_blocking == api::LineBlocking::located;
}

// What the forward pass and the shading read of the LPV: its cascades when it ran, else none.
IndirectLightInputs FrameExecutor::indirect_light(const Frame& frame) const {
  return {frame.resources.lpv_uniforms, *frame.resources.volumes,
          frame.plan.run[kInject] ? std::uint32_t(frame.lpv.cascades.size()) : 0u, walls_located(frame)};
}

// Records one pass (for the grid passes: one cascade of it), bracketed by the pass timer.
void FrameExecutor::record_pass(Pass pass, std::uint32_t cascade, Steps steps, const Frame& frame) {
  const VkCommandBuffer cmd = commands_.begin();
  const api::Lpv& lpv = frame.request.lpv;
  timer_.begin(cmd);
  // The camera's raster pass (G-buffer or forward) is the first to bind the shadow atlas: it
  // needs its layout even when no map was drawn (no light samples it then).
  if ((pass == kGBuffer || pass == kForward) && !frame.plan.run[kShadow]) ShadowPass::record_skipped(cmd, *frame.resources.atlas);
  // The first grid pass (the geometry volume, else the injection: pass_schedule) is the first
  // to bind the RSMs: their layout too when no light drew them.
  const bool first_grid_pass = cascade == 0 && (pass == kGeometryVolume || (pass == kInject && !frame.plan.run[kGeometryVolume]));
  if (first_grid_pass && !frame.plan.run[kRsm]) RsmPass::record_skipped(cmd, *frame.resources.rsm_maps);
  switch (pass) {
    case kShadow:
      shadow_.record(cmd, frame.gpu, *frame.resources.atlas, frame.lights.shadow_views);
      break;
    case kRsm:
      rsm_.record(cmd, frame.gpu, *frame.resources.rsm_maps, frame.resources.rsm_view_buffer, frame.lpv.rsm_views,
                  frame.resources.light_buffer);
      break;
    case kGBuffer:
      gbuffer_.record(cmd, frame.gpu, frame.draw_order, frame.resources.targets->camera, frame.resources.frame_uniforms);
      break;
    case kInject:
      inject_.record(cmd, cascade, frame.resources.lpv_uniforms, frame.plan.run[kRsm] ? &*frame.resources.rsm_maps : nullptr,
                     frame.lpv.rsm_views, lpv, frame.lpv.cascades[cascade].cell_size, frame.gpu, *frame.resources.volumes,
                     walls_located(frame));
      break;
    case kGeometryVolume: {
      if (cascade == 0) {  // the camera's surfels, drawn once for every cascade (timed with the first)
        if (lpv.occlusion_from_camera)
          gbuffer_.record(cmd, frame.gpu, frame.draw_order, frame.resources.targets->surfels, frame.resources.frame_uniforms);
        else
          GBufferPass::record_unused(cmd, frame.resources.targets->surfels);
      }
      GeometrySources sources = geometry_sources(lpv, frame.plan.run[kRsm]);
      sources.bounces = frame.lpv.bounces;
      sources.covers = frame.plan.run[kGather] && lpv.line_blocking != api::LineBlocking::multiplied;
      sources.walls = walls_located(frame);
      geometry_.record(cmd, cascade, frame.resources.lpv_uniforms, *frame.resources.rsm_maps, frame.lpv.rsm_views,
                       frame.resources.targets->surfels, frame.gpu, sources, *frame.resources.volumes);
      break;
    }
    case kPropagate:
      propagate_.record(cmd, cascade, steps.first, steps.count, frame.lpv.occlusion, frame.lpv.bounces, frame.resources.lpv_uniforms,
                       *frame.resources.volumes);
      break;
    case kGather:
      gather_.record(cmd, cascade, steps.first - 1, steps.count, {frame.lpv.occlusion, lpv.far_lines, lpv.line_blocking},
                     {gathered_bounces(lpv.bounces), &frame.gpu.blockers, frame.gpu.blocker_count, lpv.injection,
                      walls_located(frame)},
                     frame.resources.lpv_uniforms, *frame.resources.volumes);
      break;
    case kForward:
      forward_.record(cmd, frame.gpu, frame.draw_order, *frame.resources.targets, direct_light(frame), indirect_light(frame),
                     frame.request.output.tonemap);
      break;
    case kShade:
      shade_.record(cmd, frame.gpu, *frame.resources.targets,
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
      if (frame.readback & kReadbackDisplay) copy(frame.resources.targets->display, frame.resources.targets->display_readback);
      if (frame.readback & kReadbackLinear) copy(frame.resources.targets->linear, frame.resources.targets->linear_readback);
      vkx::memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
      break;
    }
    case kPassCount:
      break;
  }
  timer_.end(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
}

}  // namespace renderer
