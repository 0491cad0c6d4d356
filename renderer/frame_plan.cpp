#include "renderer/frame_plan.hpp"

#include "api/counted.hpp"
#include "renderer/gpu_types.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <limits>

namespace renderer {
namespace {

// Propagated light does not cross in a straight line: the side faces spread it sideways
// every step, so it takes more steps than the distance. Twice the L1 diameter loses under
// 1% of the indirect light on the built-in scenes (docs/planner.md); once loses 6%.
constexpr float kCrossings = 2.0f;

// RSM texels per cell side, at the farthest point of the scene a light view sees
// (gpu::LPV_VPLS_PER_CELL_SIDE says why 4). It keeps every built-in default at the requested
// resolution and still cuts narrow spots and small scenes (docs/planner.md).
constexpr float kTexelsPerCell = float(gpu::LPV_VPLS_PER_CELL_SIDE);

float distance_to_box(glm::vec3 p, const scene::Bounds& b) {
  return glm::length(glm::max(glm::max(b.min - p, p - b.max), glm::vec3(0.0f)));
}

bool reflects_light(const scene::Scene& s) {
  return std::any_of(s.materials.begin(), s.materials.end(),
                     [](const scene::Material& m) { return glm::any(glm::greaterThan(m.base_color, glm::vec3(0.0f))); });
}

}  // namespace

bool needs_direct_light(api::View v) { return v == api::View::final_ || v == api::View::direct; }
bool needs_indirect_light(api::View v) {
  return v == api::View::final_ || v == api::View::indirect || v == api::View::lpv;
}

std::string light_misses(const api::Light& light, const scene::Bounds& bounds) {
  if (light.type == api::LightType::directional) return {};
  if (light.range > 0.0f && distance_to_box(light.position, bounds) > light.range)
    return "the scene is beyond its range";
  if (light.type != api::LightType::spot) return {};
  // The cone against the scene's bounding sphere (which holds the box): missed when the
  // sphere lies wholly outside the cone.
  const glm::vec3 to_center = bounds.center() - light.position;
  const float distance = glm::length(to_center);
  const float radius = bounds.radius();
  if (distance <= radius) return {};
  const float angle = std::acos(std::clamp(glm::dot(light.direction, to_center / distance), -1.0f, 1.0f));
  const float sphere = std::asin(std::min(1.0f, radius / distance));
  return angle - sphere > glm::radians(light.outer_cone_deg) ? "its cone points away from the scene" : "";
}

std::uint32_t iterations_needed(const CascadePlacement& cascade, const scene::Bounds& bounds, std::uint32_t requested) {
  const glm::vec3 lo = glm::max(bounds.min, cascade.origin);
  const glm::vec3 hi = glm::min(bounds.max, cascade.origin + glm::vec3(cascade.dims) * cascade.cell_size);
  const glm::vec3 cells = glm::ceil(glm::max(hi - lo, glm::vec3(0.0f)) / cascade.cell_size);
  const float diameter = std::max(1.0f, cells.x + cells.y + cells.z);
  return std::min(requested, std::uint32_t(kCrossings * diameter));
}

std::vector<std::uint32_t> rsm_view_resolutions(const std::vector<LightView>& views,
                                                const std::vector<api::Light>& lights, const scene::Bounds& bounds,
                                                float cell_size, std::uint32_t requested) {
  const std::array<glm::vec3, 2> ends{bounds.min, bounds.max};
  std::vector<std::uint32_t> resolutions;
  for (const LightView& view : views) {
    // A texel's side: 2 * half_extent / resolution, times the distance for a perspective view.
    float side = 2.0f * view.half_extent;
    if (!view.orthographic) {
      // The farthest point of the bounds the view may see: no farther than the farthest corner,
      // and no farther than the deepest corner along the view's axis allows inside its frustum
      // (a point at depth t lies within t sqrt(1 + 2 half_extent^2) of the light). A cube face
      // that looks at a near wall needs a fraction of the one that looks down a corridor.
      const glm::vec3 p = lights[view.light].position;
      const glm::vec3 farthest = glm::max(glm::abs(bounds.min - p), glm::abs(bounds.max - p));
      float depth = 0.0f;
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c(ends[corner & 1].x, ends[(corner >> 1) & 1].y, ends[corner >> 2].z);
        depth = std::max(depth, glm::dot(c - p, view.axis));
      }
      const float in_frustum = depth * std::sqrt(1.0f + 2.0f * view.half_extent * view.half_extent);
      side *= std::min(glm::length(farthest), in_frustum);
    }
    const float needed = std::min(side * kTexelsPerCell / cell_size, float(requested));
    // Rounded up to whole tiles of the injection's work groups, not to a power of two, which
    // could nearly double it: the RSM's cost and the injection's follow its square.
    constexpr std::uint32_t kStep = gpu::LPV_VPL_GROUP * gpu::LPV_INJECT_TILE;
    const std::uint32_t steps = std::max(1u, std::uint32_t(std::ceil(needed / float(kStep))));
    resolutions.push_back(std::min(steps * kStep, requested));
  }
  return resolutions;
}

namespace {

// The union of the bounds of the draws `counts` picks, or the scene's when it picks none.
template <class Counts>
scene::Bounds draws_bounds(const scene::Scene& scene, Counts counts) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (std::size_t d = 0; d < scene.draw_bounds.size(); ++d) {
    if (!counts(d)) continue;
    lo = glm::min(lo, scene.draw_bounds[d].min);
    hi = glm::max(hi, scene.draw_bounds[d].max);
  }
  return lo.x <= hi.x ? scene::Bounds{lo, hi} : scene.bounds;
}

}  // namespace

std::uint32_t shadow_resolution_for(const std::vector<LightView>& views, const std::vector<bool>& shadowed,
                                    const std::vector<api::Light>& lights, const ShadowSight& sight) {
  const float pixel = sight.pixel_per_metre * glm::length(sight.receiver - sight.eye);
  float needed = 0.0f;
  std::uint64_t layers = 0;  // shadow maps: a point light's cube is 6
  for (const LightView& view : views) {
    if (!shadowed.empty() && !shadowed[view.light]) continue;
    ++layers;
    // A texel's side at the receiver: 2 * half_extent / resolution, times the distance for a
    // perspective view.
    float side = 2.0f * view.half_extent;
    if (!view.orthographic) side *= glm::length(sight.receiver - lights[view.light].position);
    if (pixel > 0.0f) needed = std::max(needed, 2.0f * side / pixel);
  }
  std::uint32_t resolution = kMinShadowResolution;
  while (float(resolution) < needed && resolution < kMaxShadowResolution) resolution *= 2;
  while (resolution > kMinShadowResolution &&
         std::uint64_t(resolution) * resolution * std::max<std::uint64_t>(layers, 1) > sight.budget_texels)
    resolution /= 2;
  return resolution;
}

glm::vec3 seen_centre(const scene::Scene& scene, const std::vector<bool>& seen) {
  return draws_bounds(scene, [&](std::size_t d) { return d < seen.size() && seen[d]; }).center();
}

std::uint32_t plan_shadow_resolution(FramePlan& plan, const api::RenderRequest& request, const scene::Scene& scene,
                                     const std::vector<api::Light>& lights, const std::vector<LightView>& views,
                                     const CameraSetup& camera, float fov_y_deg, std::uint64_t budget_texels) {
  if (request.shadows.resolution) return *request.shadows.resolution;
  ShadowSight sight;
  sight.receiver = seen_centre(scene, plan.draw_seen);
  sight.eye = camera.position;
  sight.pixel_per_metre = 2.0f * std::tan(0.5f * glm::radians(fov_y_deg)) / float(request.output.height);
  sight.budget_texels = std::min(budget_texels, kShadowTexelBudget);
  const std::uint32_t resolution = shadow_resolution_for(views, plan.light_shadowed, lights, sight);
  // The decisions say what differs from the documented default, the least resolution.
  if (plan.run[kShadow] && resolution > kMinShadowResolution)
    plan.decisions.push_back("shadow maps " + std::to_string(resolution) + " texels per side, not " +
                             std::to_string(kMinShadowResolution) +
                             ": a texel at most half a pixel wide where the camera looks");
  return resolution;
}

namespace {

// Whether a box may be inside the view frustum of `view_proj` (Vulkan clip space, depth
// 0..1): not when all its corners are outside one plane.
bool may_be_visible(const scene::Bounds& b, const glm::mat4& view_proj) {
  std::array<glm::vec4, 8> clip;
  for (int i = 0; i < 8; ++i)
    clip[std::size_t(i)] = view_proj * glm::vec4(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                                                  i & 4 ? b.max.z : b.min.z, 1.0f);
  auto all_outside = [&](auto outside) {
    return std::all_of(clip.begin(), clip.end(), outside);
  };
  return !(all_outside([](const glm::vec4& c) { return c.x < -c.w; }) ||
           all_outside([](const glm::vec4& c) { return c.x > c.w; }) ||
           all_outside([](const glm::vec4& c) { return c.y < -c.w; }) ||
           all_outside([](const glm::vec4& c) { return c.y > c.w; }) ||
           all_outside([](const glm::vec4& c) { return c.z < 0.0f; }) ||
           all_outside([](const glm::vec4& c) { return c.z > c.w; }));
}

}  // namespace

std::vector<bool> draws_seen(const scene::Scene& scene, const glm::mat4& view_proj) {
  std::vector<bool> seen;
  for (const scene::Bounds& b : scene.draw_bounds) seen.push_back(may_be_visible(b, view_proj));
  return seen;
}

bool may_cast_shadows(const scene::Scene& scene, const api::Light& light, const std::vector<bool>& seen) {
  const std::size_t n = scene.draw_bounds.size();
  if (n > kMaxShadowTestDraws || scene.draw_planar.size() != n || seen.size() != n) return true;
  auto overlaps = [](const scene::Bounds& a, const scene::Bounds& b) {
    return glm::all(glm::lessThanEqual(a.min, b.max)) && glm::all(glm::lessThanEqual(b.min, a.max));
  };
  for (std::size_t r = 0; r < n; ++r) {  // receivers
    const scene::Bounds& b = scene.draw_bounds[r];
    if (!seen[r] || !light_misses(light, b).empty()) continue;
    if (!scene.draw_planar[r]) return true;
    // The box spanned by the receiver and the light: what lies between them is inside it.
    scene::Bounds between = b;
    if (light.type == api::LightType::directional) {
      const glm::vec3 toward = -light.direction * (2.0f * scene.bounds.radius() + glm::length(b.max - b.min));
      between = {glm::min(b.min, b.min + toward), glm::max(b.max, b.max + toward)};
    } else {
      between = {glm::min(b.min, light.position), glm::max(b.max, light.position)};
    }
    for (std::size_t o = 0; o < n; ++o)
      if (o != r && overlaps(scene.draw_bounds[o], between)) return true;
  }
  return false;
}

namespace {

// Whether some corner of box b lies in front of the plane (n, w): beyond `tolerance`, on
// either side for a double-sided surface.
bool reaches_in_front(const scene::Bounds& b, glm::vec4 plane, bool double_sided, float tolerance) {
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
    const float height = glm::dot(glm::vec3(plane), corner) - plane.w;
    if (height > tolerance || (double_sided && height < -tolerance)) return true;
  }
  return false;
}

}  // namespace

bool surfaces_may_light_each_other(const scene::Scene& scene) {
  const std::size_t n = scene.draws.size();
  if (n > kMaxShadowTestDraws || scene.draw_planar.size() != n || scene.draw_plane.size() != n ||
      scene.draw_bounds.size() != n)
    return true;
  if (!std::all_of(scene.draw_planar.begin(), scene.draw_planar.end(), [](bool planar) { return planar; })) return true;
  // Within a millionth of the scene's extent of a plane is on it (scene::Scene::draw_planar's).
  const float tolerance = 1e-6f * glm::length(scene.bounds.max - scene.bounds.min);
  auto double_sided = [&](std::size_t d) {
    const std::uint32_t m = scene.draws[d].material;
    return m < scene.materials.size() && scene.materials[m].double_sided;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (reaches_in_front(scene.draw_bounds[b], scene.draw_plane[a], double_sided(a), tolerance) &&
          reaches_in_front(scene.draw_bounds[a], scene.draw_plane[b], double_sided(b), tolerance))
        return true;
  return false;
}

scene::Bounds lpv_region(const scene::Scene& scene, const std::vector<bool>& seen,
                         const std::vector<api::Light>& lights, const std::vector<bool>& light_drawn) {
  return draws_bounds(scene, [&](std::size_t d) {
    bool matters = seen[d];
    for (std::size_t i = 0; i < lights.size() && !matters; ++i)
      matters = light_drawn[i] && light_misses(lights[i], scene.draw_bounds[d]).empty();
    return matters;
  });
}

std::uint32_t cascades_needed(const std::vector<CascadePlacement>& cascades, const scene::Bounds& bounds) {
  for (std::uint32_t c = 0; c + 1 < cascades.size(); ++c) {
    // Shading samples half a cell off the surface and blends over the last LPV_BLEND_CELLS
    // of a cascade.
    const float margin = (float(gpu::LPV_BLEND_CELLS) + 0.5f) * cascades[c].cell_size;
    const glm::vec3 lo = cascades[c].origin + margin;
    const glm::vec3 hi = cascades[c].origin + glm::vec3(cascades[c].dims) * cascades[c].cell_size - margin;
    if (glm::all(glm::lessThanEqual(lo, bounds.min)) && glm::all(glm::lessThanEqual(bounds.max, hi))) return c + 1;
  }
  return std::uint32_t(cascades.size());
}

FramePlan plan_frame(const PlanInputs& in) {
  const api::RenderRequest& request = in.request;
  FramePlan plan;
  plan.draw_seen = draws_seen(in.scene, in.camera_view_proj);
  const api::View view = request.output.view;
  const std::string view_name = "view '" + api::to_string(view) + "'";
  plan.run[kGBuffer] = plan.run[kShade] = plan.run[kReadback] = true;

  // Lights: those that emit get views, unless (auto) they cannot reach the scene.
  bool any_drawn = false, any_shadowed = false;
  for (std::size_t i = 0; i < in.lights.size(); ++i) {
    const api::Light& light = in.lights[i];
    std::string misses =
        api::plan_applies(request, api::PlanRule::lights) && emits(light) ? light_misses(light, in.scene.bounds) : "";
    if (!misses.empty())
      plan.decisions.push_back("light " + std::to_string(i) + ": no shadow map or RSM, " + misses);
    plan.light_drawn.push_back(emits(light) && misses.empty());
    any_drawn = any_drawn || plan.light_drawn.back();
    const bool shadowed = plan.light_drawn.back() && request.shadows.enabled && needs_direct_light(request.output.view) &&
                          (!api::plan_applies(request, api::PlanRule::shadows) ||
                           may_cast_shadows(in.scene, light, plan.draw_seen));
    if (plan.light_drawn.back() && request.shadows.enabled && needs_direct_light(request.output.view) && !shadowed)
      plan.decisions.push_back("light " + std::to_string(i) + ": no shadow map, nothing can cast its shadow on what the camera sees");
    plan.light_shadowed.push_back(shadowed);
    any_shadowed = any_shadowed || shadowed;
  }

  if (!needs_direct_light(view))
    plan.reason[kShadow] = view_name + " needs no direct light";
  else if (!request.shadows.enabled)
    plan.reason[kShadow] = "shadows disabled";
  else if (!any_drawn)
    plan.reason[kShadow] = "no light reaches the scene";
  else if (!any_shadowed)
    plan.reason[kShadow] = "nothing can cast a shadow on what the camera sees";
  plan.run[kShadow] = plan.reason[kShadow].empty();
  if (!needs_direct_light(view)) plan.reason[kShade] = view_name + ": shaded without the lights' direct light";

  const bool reflects = !api::plan_applies(request, api::PlanRule::surfaces) || reflects_light(in.scene);
  const bool vpls = (any_drawn && reflects) || in.emitters > 0;
  std::string lpv_reason;
  if (!needs_indirect_light(view))
    lpv_reason = view_name + " needs no indirect light";
  else if (!request.lpv.enabled)
    lpv_reason = "lpv disabled";
  else if (request.lpv.intensity == 0.0f && view != api::View::lpv)
    lpv_reason = "lpv.intensity is 0";
  else if (!any_drawn && in.emitters == 0)
    lpv_reason = "no light reaches the scene and no surface is emissive";
  else if (!vpls)
    lpv_reason = "every albedo is 0: nothing reflects light, and no surface is emissive";
  else if (view != api::View::lpv && api::plan_applies(request, api::PlanRule::surfaces) &&
           !surfaces_may_light_each_other(in.scene))
    lpv_reason = "no surface can light another: every one is planar and none lies in front of another";
  for (Pass p : {kRsm, kInject, kGeometryVolume, kPropagate, kGather}) plan.reason[p] = lpv_reason;
  // Black surfaces still block light: their RSM stays when it is a source of occluders.
  const bool rsm_occludes = request.lpv.occlusion && request.lpv.occlusion_from_rsm;
  if (lpv_reason.empty()) {
    if (!any_drawn)
      plan.reason[kRsm] = "no light reaches the scene (emissive surfaces inject directly)";
    else if (!reflects && !rsm_occludes)
      plan.reason[kRsm] = "every albedo is 0: nothing reflects light (emissive surfaces inject directly)";
    if (!request.lpv.occlusion)
      plan.reason[kGeometryVolume] = "occlusion disabled";
    else if (!request.lpv.occlusion_from_camera && !request.lpv.occlusion_from_scene && !any_drawn)
      plan.reason[kGeometryVolume] = "no occluders: occlusion_sources is only \"rsm\" and no light draws an RSM";
    // One of the two carries the injected light to the cells the shading reads.
    if (request.lpv.transfer == api::Transfer::gather) {
      plan.reason[kPropagate] = "lpv.transfer is \"gather\": every cell gathers the injected light itself";
    } else {
      plan.reason[kGather] = "lpv.transfer \"" + api::to_string(request.lpv.transfer) + "\" propagates the light";
      if (request.lpv.iterations == 0) plan.reason[kPropagate] = "0 iterations";
    }
  }
  for (Pass p : {kRsm, kInject, kGeometryVolume, kPropagate, kGather}) plan.run[p] = plan.reason[p].empty();
  plan.convergence = api::plan_applies(request, api::PlanRule::convergence) ? request.lpv.convergence : 0.0f;
  return plan;
}

void plan_shading(FramePlan& plan, api::View view, bool display_only) {
  std::string& why_not = plan.reason[kForward];
  if (view != api::View::final_ && view != api::View::direct)
    why_not = "view '" + api::to_string(view) + "' is shaded from the G-buffer";
  else if (!display_only)
    why_not = "a linear image is wanted: shaded from the G-buffer";
  plan.run[kForward] = why_not.empty();
  if (!plan.run[kForward]) return;
  plan.run[kGBuffer] = plan.run[kShade] = plan.run[kReadback] = false;
  plan.reason[kGBuffer] = plan.reason[kShade] = "only the 8-bit image is wanted: shaded by the forward pass";
  plan.reason[kReadback] = "the forward pass copies its image to the host itself";
}

std::string transfer_choice(const api::Lpv& resolved) {
  const glm::uvec3 g = resolved.grid;
  const std::string cells = std::to_string(g.x) + "x" + std::to_string(g.y) + "x" + std::to_string(g.z) + " cells";
  const std::string limit = std::to_string(api::limits::max_gather_cells);
  if (resolved.transfer == api::Transfer::gather) return "transfer gather (auto): " + cells + ", within its " + limit;
  return "transfer " + api::to_string(resolved.transfer) + " (auto): " + cells + " are more than the gather's " + limit;
}

namespace {

// "64" when every view has the same resolution, else "256 (2 light views), 64 (4)", the
// largest first.
std::string describe_view_resolutions(std::vector<std::uint32_t> resolutions) {
  std::sort(resolutions.begin(), resolutions.end(), std::greater<>());
  if (resolutions.front() == resolutions.back()) return std::to_string(resolutions.front());
  std::string text;
  for (std::size_t i = 0; i < resolutions.size();) {
    std::size_t n = 1;
    while (i + n < resolutions.size() && resolutions[i + n] == resolutions[i]) ++n;
    text += (text.empty() ? "" : ", ") + std::to_string(resolutions[i]) + " (" +
            (text.empty() ? api::counted(n, "light view") : std::to_string(n)) + ")";
    i += n;
  }
  return text;
}

}  // namespace

LpvPlan plan_lpv(FramePlan& plan, const api::RenderRequest& request, const scene::Scene& scene,
                 const LpvFrameInputs& frame) {
  LpvPlan lpv{scene.bounds, request.lpv, {}, {}, {}};
  const std::vector<api::Light>& lights = frame.lights;
  const std::vector<LightView>& views = frame.views;
  // The cascades placed over the grid's bounds with the settings as they stand.
  auto fit = [&] {
    LpvSetup setup = setup_lpv(lpv.settings, lpv.rsm_view_resolutions, scene.bounds, lpv.grid_bounds, lights, views,
                               frame.emitted_flux, frame.camera, frame.fov_y_deg, frame.image_height);
    // Without a geometry volume this frame (no occluders), propagation does not read one. The
    // gather's bounces reflect from the scene's surfels, not from the blockers' albedo.
    if (!plan.run[kGeometryVolume]) setup.occlusion = setup.bounces = false;
    if (plan.run[kGather]) setup.bounces = false;
    return setup;
  };
  // The grid covers only what the camera sees and the lights reach (unless placed by hand).
  if (api::plan_applies(request, api::PlanRule::grid) && plan.run[kInject] && !request.lpv.origin && !request.lpv.extent) {
    lpv.grid_bounds = lpv_region(scene, plan.draw_seen, lights, plan.light_drawn);
    const float fitted = glm::length(lpv.grid_bounds.max - lpv.grid_bounds.min);
    const float whole = glm::length(scene.bounds.max - scene.bounds.min);
    if (fitted < 0.999f * whole)
      plan.decisions.push_back("grid fitted to the part of the scene the camera sees and the lights reach (" +
                               std::to_string(fitted) + " of " + std::to_string(whole) + " m across)");
  }
  // The gather's cost is its cell count, however arranged: it spends them on the region's shape.
  // (Propagation's range and iterations are counted in cells along each axis: it keeps its cube.)
  if (api::plan_applies(request, api::PlanRule::grid) && plan.run[kGather] && !request.lpv.origin &&
      !request.lpv.extent) {
    const glm::uvec3 shaped = grid_shaped_to(request.lpv.grid, lpv.grid_bounds);
    if (shaped != request.lpv.grid) {
      plan.decisions.push_back("grid " + std::to_string(shaped.x) + "x" + std::to_string(shaped.y) + "x" +
                               std::to_string(shaped.z) + ": the gather's cells (no more than " +
                               std::to_string(request.lpv.grid.x) + "x" + std::to_string(request.lpv.grid.y) + "x" +
                               std::to_string(request.lpv.grid.z) + ") arranged to the shape of the grid's region");
      lpv.settings.grid = shaped;
    }
  }
  // Propagation reflects the light its blockers stop at every step: 2 is all it can do.
  const std::string asked = request.lpv.bounces == api::all_bounces ? "all" : std::to_string(request.lpv.bounces);
  if (plan.run[kPropagate] && request.lpv.bounces > 2) {
    plan.decisions.push_back("lpv.bounces " + asked +
                             ": 2 ran, propagation reflects the light its blockers stop as it goes (the gather runs "
                             "one gather a bounce)");
    lpv.settings.bounces = 2;
  }
  if (plan.run[kGather] && request.lpv.bounces == api::all_bounces)
    plan.decisions.push_back("lpv.bounces all: " + std::to_string(api::limits::gathered_before_tail) +
                             " gathered, the rest estimated from the last one's light and the share of it its "
                             "surfaces reflect (stats.lpv.cascades[].bounce_tail)");
  lpv.setup = fit();

  if (api::plan_applies(request, api::PlanRule::rsm) && plan.run[kRsm] && !views.empty()) {
    const std::uint32_t requested = request.lpv.rsm_resolution;
    std::vector<std::uint32_t> needed =
        rsm_view_resolutions(views, lights, lpv.grid_bounds, lpv.setup.cascades[0].cell_size, requested);
    const auto [smallest, largest] = std::minmax_element(needed.begin(), needed.end());
    if (*smallest < requested) {
      plan.decisions.push_back("rsm " + describe_view_resolutions(needed) + " of " + std::to_string(requested) +
                               " texels per side: four texels a cell on the farthest surface " +
                               (*smallest == *largest ? "the lights see" : "each light view sees"));
      lpv.settings.rsm_resolution = *largest;
      lpv.settings.vpl_downsample = std::min(lpv.settings.vpl_downsample, *smallest);
      lpv.rsm_view_resolutions = std::move(needed);
      lpv.setup = fit();
    }
  }

  if (api::plan_applies(request, api::PlanRule::cascades) && plan.run[kInject]) {
    const std::uint32_t needed = cascades_needed(lpv.setup.cascades, lpv.grid_bounds);
    if (needed < lpv.setup.cascades.size()) {
      plan.decisions.push_back(std::to_string(needed) + " of " + std::to_string(lpv.setup.cascades.size()) +
                               " cascades: cascade " + std::to_string(needed - 1) +
                               " holds the whole scene, the coarser ones add nothing");
      lpv.setup.cascades.resize(needed);
    }
  }

  // Propagation steps per cascade: as requested, or no more than light needs to cross the
  // part of the scene inside the cascade.
  lpv.iterations.assign(lpv.setup.cascades.size(), request.lpv.iterations);
  if (!api::plan_applies(request, api::PlanRule::iterations) || !plan.run[kPropagate]) return lpv;
  for (std::uint32_t c = 0; c < lpv.iterations.size(); ++c) {
    lpv.iterations[c] = iterations_needed(lpv.setup.cascades[c], lpv.grid_bounds, request.lpv.iterations);
    if (lpv.iterations[c] < request.lpv.iterations)
      plan.decisions.push_back("cascade " + std::to_string(c) + ": " + std::to_string(lpv.iterations[c]) + " of " +
                               std::to_string(request.lpv.iterations) +
                               " iterations, as many as light needs to cross the scene's cells in it");
  }
  return lpv;
}

}  // namespace renderer
