// Pure maths that turns a request's LPV settings into what the LPV passes consume: where each
// cascade sits, the fixed-point scales of the deterministic accumulation, and the RSM views.
// No Vulkan here, so all of it is unit-tested on its own.
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/gpu_types.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace renderer {

struct CascadePlacement {
  glm::vec3 origin{0.0f};  // minimum corner, metres
  float cell_size = 1.0f;  // metres; cells are cubes
  glm::uvec3 dims{1};      // cells per axis
};

// Cascade 0 is the finest; each next one has cells twice as large and the same dims. With
// lpv.origin / lpv.extent given, cascade 0 is exactly that box (extent = its longest edge);
// otherwise the outermost cascade is fitted around the scene bounds and the inner ones are
// centred on `focus`. Cascades other than a given one are snapped to whole cells of their
// own size, so that a moving focus does not make the lighting crawl.
std::vector<CascadePlacement> place_cascades(const api::Lpv& lpv, const scene::Bounds& bounds, glm::vec3 focus);

// The cells of `requested` (no more than its count) arranged to the shape of `bounds`: cubic
// cells, as many along each axis as place_cascades needs to hold the bounds with half a cell
// to spare, the cells as small as the count allows (each axis 2 to api::limits::max_grid_side).
// An 8 x 1.5 x 2.5 m corridor gets 8 x 13 x 38 cells of 0.22 m for 16^3, where a cube of 16^3
// spends 0.53 m cells, 3 across it, on the empty space beside it. `requested` itself when no
// arrangement fits (a flat or empty box gets 2 cells across its thin axes).
glm::uvec3 grid_shaped_to(glm::uvec3 requested, const scene::Bounds& bounds);

// An upper bound of the flux all VPLs can carry (W): what the lights send toward the scene,
// reflected with albedo at most 1. Zero when no light emits.
double vpl_flux_bound(const std::vector<api::Light>& lights, const scene::Bounds& bounds);

// The fixed-point scale of the flux accumulators: a power of two (so scaling is exact) that
// leaves 2^60 units for the bound, far from the int64 limit whatever the light's magnitude.
float flux_units_per_watt(double flux_bound);

// The factors on the directional (band-1) terms of the lobes a transfer propagates and
// injects (GpuLpv::transfer): 1 and 1 for cosine lobes, LPV_SHARPENED_TRANSFER and
// LPV_SHARPENED_INJECTION (shaders/shared/lpv_sh.h) for the sharpened transfer.
struct TransferFactors {
  float propagated = 1.0f;
  float injected = 1.0f;
};
TransferFactors transfer_factors(api::Transfer transfer);

// Texels a cell and channel of the light the shading reads: SH for the propagating transfers,
// the gather's irradiance cube (LpvVolumes::accumulated).
inline std::uint32_t accumulated_texels_per_cell(api::Transfer transfer) { return transfer == api::Transfer::gather ? 2 : 1; }

// The gather's bounces for lpv.bounces: that many gathered, or for "all" (api::all_bounces)
// api::limits::gathered_before_tail and an estimate of the rest (docs/lpv.md, "Bounces").
struct GatheredBounces {
  std::uint32_t gathered = 1;
  bool tail = false;
};
inline GatheredBounces gathered_bounces(std::uint32_t bounces) {
  if (bounces == api::all_bounces) return {api::limits::gathered_before_tail, true};
  return {bounces, false};
}

// Geometry volume: fixed-point units per unit of blocking potential.
inline constexpr float kGeometryUnitsPerPotential = 1048576.0f;  // 2^20

struct LpvSetup {
  std::vector<CascadePlacement> cascades;
  // What propagation runs with: blocking by the geometry volume, and the light it reflects.
  bool occlusion = false;
  bool bounces = false;
  gpu::GpuLpv gpu{};
  std::vector<gpu::GpuRsmView> rsm_views;
};

// Every how many pixels (each way) a geometry volume source of `rows` rows (the camera's
// image, an RSM) gives a surfel: about 128 rows of surfels from each.
std::uint32_t surfel_stride(std::uint32_t rows);

// VPLs per side of a light view (gpu::GpuRsmView::info.z texels a side): the RSM's texels,
// merged vpl_downsample^2 at a time.
inline std::uint32_t vpls_per_view_side(const gpu::GpuRsmView& view, const api::Lpv& lpv) {
  return view.info.z / lpv.vpl_downsample;
}

// Everything the LPV passes of one frame need. `views` are the emitting lights' views, drawn
// into RSMs of `view_resolutions` texels a side (empty: lpv.rsm_resolution, the maps' side);
// `emitted_flux` is the largest channel of the emissive surfaces' flux (W), injected too.
// Fitted cascades cover `grid_bounds` (the scene's, or the part the planner chose); the
// fixed-point range covers all the flux the lights send into `bounds`, the whole scene's.
LpvSetup setup_lpv(const api::Lpv& lpv, const std::vector<std::uint32_t>& view_resolutions, const scene::Bounds& bounds,
                   const scene::Bounds& grid_bounds, const std::vector<api::Light>& lights,
                   const std::vector<LightView>& views, double emitted_flux, const CameraSetup& camera,
                   float camera_fov_y_deg, std::uint32_t image_height);

}  // namespace renderer
