// The planner: before anything is recorded, decides which passes of a frame run, for which
// lights, and how many propagation steps, from the request and the scene, and says why.
// With plan "exact" only the request decides (what it disables or its view does not show
// is skipped); with "auto" (the default) what cannot change the image is skipped too.
// Pure CPU maths: unit-tested without a device (docs/planner.md).
#pragma once

#include "api/render_request.hpp"
#include "renderer/frame_setup.hpp"
#include "renderer/lpv/lpv_setup.hpp"
#include "scene/scene.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace renderer {

// The passes of a frame. The LPV grid passes run once per cascade.
enum Pass : std::uint32_t {
  kShadow,
  kRsm,
  kGBuffer,
  kInject,
  kGeometryVolume,
  kPropagate,
  kGather,
  kForward,
  kShade,
  kReadback,
  kPassCount
};
inline constexpr std::array<const char*, kPassCount> kPassNames = {
    "shadow", "rsm", "gbuffer", "inject", "geometry_volume", "propagate", "gather", "forward", "shade", "readback"};
inline bool is_grid_pass(std::uint32_t p) {
  return p == kInject || p == kGeometryVolume || p == kPropagate || p == kGather;
}

bool needs_direct_light(api::View v);
bool needs_indirect_light(api::View v);

struct FramePlan {
  std::array<bool, kPassCount> run{};
  std::array<std::string, kPassCount> reason;
  std::vector<bool> light_drawn;       // per light: it gets RSM views (and shadow maps if shadowed)
  std::vector<bool> light_shadowed;    // per light: something may cast its shadow on what is seen
  std::vector<bool> draw_seen;         // per draw: may be inside the camera's frustum (by its bounds)
  float convergence = 0.0f;            // stop when the rest would add less than this share (0: never)
  std::vector<std::string> decisions;  // what the plan changed from the request, and why
};

struct PlanInputs {
  const api::RenderRequest& request;
  const std::vector<api::Light>& lights;  // the request's lights, resolved against the scene's
  const scene::Scene& scene;
  std::uint32_t emitters = 0;  // emissive surfels of the scene
  glm::mat4 camera_view_proj{1.0f};
};

FramePlan plan_frame(const PlanInputs& in);

// What setup_lpv places the cascades from, besides the grid's bounds and the LPV settings:
// the frame's lights and their views, the emissive surfaces' flux and the camera.
struct LpvFrameInputs {
  const std::vector<api::Light>& lights;
  const std::vector<LightView>& views;
  double emitted_flux = 0.0;
  const CameraSetup& camera;
  float fov_y_deg = 0.0f;
  std::uint32_t image_height = 0;
};

// The LPV part of a frame, once the lights' views are known: the region the grid covers,
// the LPV settings the frame runs with, the cascades and each one's propagation steps.
// Under "auto" the settings may have a lower rsm_resolution (and vpl_downsample) than the
// request's; the decisions go to `plan`. A frame without a geometry volume propagates
// without occlusion.
struct LpvPlan {
  scene::Bounds grid_bounds;
  api::Lpv settings;
  // Each light view's RSM resolution, at most settings.rsm_resolution, the maps' side (empty:
  // every view at that side).
  std::vector<std::uint32_t> rsm_view_resolutions;
  LpvSetup setup;
  std::vector<std::uint32_t> iterations;  // per cascade
};
LpvPlan plan_lpv(FramePlan& plan, const api::RenderRequest& request, const scene::Scene& scene,
                 const LpvFrameInputs& frame);

// What transfer "auto" chose for these settings (resolved: api::resolved_transfer), and why.
std::string transfer_choice(const api::Lpv& resolved);

// Why a light cannot light anything in `bounds` (empty when it may): beyond its range, or
// its cone pointing away from them.
std::string light_misses(const api::Light& light, const scene::Bounds& bounds);

// Whether anything can cast a shadow of `light` onto a draw the camera may see: a draw that
// is not planar (it may shadow itself), or another draw inside the box spanned by a seen,
// lit draw and the light (toward the light, for a directional one). By bounds, so "may".
// Scenes of more than kMaxShadowTestDraws draws are taken to need shadows.
// `seen`: draw_seen() of the frame's camera.
bool may_cast_shadows(const scene::Scene& scene, const api::Light& light, const std::vector<bool>& seen);

// Whether light reflected or emitted by one surface can reach another: not when every draw
// is planar and, of every two, one lies wholly on or behind the other's plane (a one-sided
// surface, emitting or reflecting, lights only what is in front of it, and is lit only from
// there; a double-sided one has two fronts). A lone plane, or a convex solid seen from
// outside: its true indirect light is exactly 0. By the draws' bounds, so "may"; scenes of
// more than kMaxShadowTestDraws draws may.
bool surfaces_may_light_each_other(const scene::Scene& scene);

// Per draw, whether its bounds may be inside the frustum of `view_proj` (Vulkan clip space).
std::vector<bool> draws_seen(const scene::Scene& scene, const glm::mat4& view_proj);
inline constexpr std::size_t kMaxShadowTestDraws = 256;

// How the camera's view is shaded, once the LPV's passes are planned: by the forward pass
// (direct light while rasterising, straight into the 8-bit image) when the frame shows the
// final or direct view without indirect light and only its 8-bit image is read back; else
// by the G-buffer and the deferred shading. The forward pass copies its image to the host
// itself, so the readback pass is skipped with it. Both modes: the two ways give the same
// picture (within one level of 8 bits), so this is a choice of method, not a simplification.
// `display_only`: the frame reads back the 8-bit image and no linear one.
void plan_shading(FramePlan& plan, api::View view, bool display_only);

// The propagation steps a cascade needs: light crosses one cell per step, so after the
// L1 diameter (in cells) of the part of the scene inside the cascade, every occupied cell
// has received all the light it can. At most `requested`.
std::uint32_t iterations_needed(const CascadePlacement& cascade, const scene::Bounds& bounds, std::uint32_t requested);

// The RSM resolution each light view needs: VPLs are summed per cell, so a texel on the
// farthest point of the scene the view may see need not be smaller than a quarter of a cell of
// the finest cascade (gpu::LPV_VPLS_PER_CELL_SIDE). Whole tiles of the injection (multiples of
// 32), each at most `requested`.
std::vector<std::uint32_t> rsm_view_resolutions(const std::vector<LightView>& views,
                                                const std::vector<api::Light>& lights, const scene::Bounds& bounds,
                                                float cell_size, std::uint32_t requested);

// What a shadow map's resolution is chosen from when the request leaves it out.
struct ShadowSight {
  glm::vec3 receiver{0.0f};      // where the camera looks: the centre of the draws it may see
  glm::vec3 eye{0.0f};           // the camera's position
  float pixel_per_metre = 0.0f;  // a pixel's width at 1 m from the eye: 2 tan(fov_y / 2) / height
  std::uint64_t budget_texels = 0;  // over all the shadowed views' maps together
};

// The shadow maps' resolution when the request leaves it out: the power of two in
// [kMinShadowResolution, kMaxShadowResolution] at which a texel of every shadowed view is at
// most half a pixel wide at `sight.receiver` (the lookups filter over about two texels, so a
// shadow's edge then blurs over no more than a pixel, as the reference's does), lowered to
// what the budget holds.
inline constexpr std::uint32_t kMinShadowResolution = 512;
inline constexpr std::uint32_t kMaxShadowResolution = 2048;
// What a frame's chosen maps may rasterise in all: two maps at the most. A point light's six
// cube faces stop at 1024 (their rasterising cost six maps' worth).
inline constexpr std::uint64_t kShadowTexelBudget = 2ull * kMaxShadowResolution * kMaxShadowResolution;
std::uint32_t shadow_resolution_for(const std::vector<LightView>& views, const std::vector<bool>& shadowed,
                                    const std::vector<api::Light>& lights, const ShadowSight& sight);

// The centre of the draws the camera may see (their bounds' union), or of the scene.
glm::vec3 seen_centre(const scene::Scene& scene, const std::vector<bool>& seen);

// The shadow maps' resolution: the request's, or where it leaves it out (in both plan modes:
// it is the default's value, not a pass skipped) shadow_resolution_for of the frame's light
// `views` within `budget_texels` (the device's) and kShadowTexelBudget, said in `plan` when
// it is over the least.
std::uint32_t plan_shadow_resolution(FramePlan& plan, const api::RenderRequest& request, const scene::Scene& scene,
                                     const std::vector<api::Light>& lights, const std::vector<LightView>& views,
                                     const CameraSetup& camera, float fov_y_deg, std::uint64_t budget_texels);

// The part of the scene the grid should cover: the draws the camera may see and the draws a
// drawn light may reach (by their bounds), since light flows from the lit ones to the seen
// ones; the scene's bounds when that is all of it or nothing.
scene::Bounds lpv_region(const scene::Scene& scene, const std::vector<bool>& seen,
                         const std::vector<api::Light>& lights, const std::vector<bool>& light_drawn);

// The cascades a frame needs: up to the first that holds the whole scene clear of its
// border band (where shading would hand over to the next one), so coarser ones add nothing.
std::uint32_t cascades_needed(const std::vector<CascadePlacement>& cascades, const scene::Bounds& bounds);

}  // namespace renderer
