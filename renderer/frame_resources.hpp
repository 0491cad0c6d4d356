// The GPU memory frames share: the camera's targets, the shadow atlas, the RSMs, the LPV's
// grids and the uniforms each frame uploads. Fitted to each frame's plan (checked against
// their budgets first, kept when the sizes did not change, freed before reallocating), so a
// run of like requests allocates once.
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_plan.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/frame_targets.hpp"
#include "renderer/gpu_types.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "renderer/lpv/lpv_volumes.hpp"
#include "renderer/passes/rsm_pass.hpp"
#include "renderer/passes/shadow_pass.hpp"
#include "vkx/resources.hpp"

#include <cstdint>
#include <optional>

namespace renderer {

// Shadow maps and RSMs live in host memory on lavapipe, and so do the grids: bounded so a
// request cannot exhaust it.
inline constexpr std::uint64_t kShadowAtlasBudgetBytes = 1ull << 30;
inline constexpr std::uint64_t kRsmBudgetBytes = 1ull << 30;
inline constexpr std::uint64_t kLpvBudgetBytes = 2ull << 30;

struct FrameResources {
  std::optional<FrameTargets> targets;
  std::optional<ShadowAtlas> atlas;
  std::optional<RsmMaps> rsm_maps;
  std::optional<LpvVolumes> volumes;  // the shading binds them even when no LPV ran
  vkx::Buffer frame_uniforms, light_buffer, shadow_view_buffer, lpv_uniforms, rsm_view_buffer;

  // Targets, shadow maps, RSMs and grids of the sizes `plan` needs for `request` (its LPV
  // settings as planned); api::DoesNotFit naming the field when one is over its budget or the
  // device's limits.
  void fit(const vkx::Device& device, const FramePlan& plan, const api::RenderRequest& request,
           const LightSetup& lights);
  // The frame's uniforms, lights, shadow views and LPV parameters, into buffers grown when
  // they are too small (the forward and RSM passes' uniform buffers sized for the most a
  // frame may have).
  void upload(const vkx::Device& device, const gpu::GpuFrame& frame, const LightSetup& lights, const LpvSetup& lpv);
};

}  // namespace renderer
