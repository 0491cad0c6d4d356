// Runs a planned, fitted frame on the device: records each pass of the schedule into the
// reusable command buffer and submits it, propagation in chunks while it may stop early (the
// convergence test between chunks) and the gather one slab at a time when it may be stopped,
// times every submission, and copies the images to the host. It owns the passes and their
// timer; the renderer plans the frame (frame_plan) and fits its memory (frame_resources).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_plan.hpp"
#include "renderer/frame_resources.hpp"
#include "renderer/frame_schedule.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/gpu_scene.hpp"
#include "renderer/lpv/lpv_setup.hpp"
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
#include "renderer/renderer.hpp"
#include "vkx/command_buffer.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace renderer {

class FrameExecutor {
 public:
  // propagate_column: RendererOptions::propagate_column.
  FrameExecutor(const vkx::Device& device, const TextureSetLayout& textures, std::uint32_t propagate_column);

  // What the passes of one frame read, fixed before the first is recorded.
  struct Frame {
    const FramePlan& plan;
    const GpuScene& gpu;
    const api::RenderRequest& request;  // as planned
    const LightSetup& lights;
    const LpvSetup& lpv;
    const std::vector<std::uint32_t>& iterations;  // propagation's, per cascade (the plan's)
    const FrameResources& resources;               // fitted to the plan, the uniforms uploaded
    unsigned readback;
    std::vector<std::uint32_t> draw_order;  // of the camera's raster passes (GpuScene::camera_order)
  };

  // Asked between submissions: a stop check (true: throw RenderStopped), progress after each
  // pass; RendererOptions::test_slowdown.
  struct Controls {
    const std::function<bool()>& stop_check;
    const std::function<void(const RenderProgress&)>& progress;
    double test_slowdown = 1.0;
  };

  struct Outcome {
    FrameTimings timings;
    std::vector<std::uint32_t> iterations_run;  // per cascade: fewer than planned where it converged
    std::vector<std::uint32_t> bounces_run;     // per cascade, gathered: likewise
  };

  // Runs the frame request.repeat times; the last frame's images go to `result` (display,
  // linear, as `frame.readback` says).
  Outcome run(const Frame& frame, const Controls& controls, RenderResult& result);

 private:
  // Steps first .. first + count - 1 of propagation (1-based), or slabs first - 1 ..
  // first + count - 2 of the gather; other passes ignore them.
  struct Steps {
    std::uint32_t first = 1;
    std::uint32_t count = 0;
  };
  void record_pass(Pass pass, std::uint32_t cascade, Steps steps, const Frame& frame);
  DirectLightInputs direct_light(const Frame& frame) const;
  IndirectLightInputs indirect_light(const Frame& frame) const;
  static bool walls_located(const Frame& frame);

  const vkx::Device& device_;
  ShadowPass shadow_;
  RsmPass rsm_;
  GBufferPass gbuffer_;
  ForwardPass forward_;
  LpvInjectPass inject_;
  GeometryVolumePass geometry_;
  LpvPropagatePass propagate_;
  LpvGatherPass gather_;
  ShadePass shade_;
  PassTimer timer_;
  vkx::ReusableCommandBuffer commands_;
};

}  // namespace renderer
