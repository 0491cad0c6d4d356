#version 450
// The gather's next bounce (docs/lpv.md, "Bounces"): every surfel of the scene (the geometry
// volume's blockers, renderer/lpv/blocker_surfels.hpp, which cover every surface whatever a
// view sees) reflects the light the last bounce's gather delivered to it, and becomes a VPL of
// the next bounce, added to the injection's sums (cleared first) as an RSM's VPLs are
// (lpv_inject_vpl.glsl). A surfel reads the irradiance as the shading reads it for a surface
// (lpv_irradiance.glsl: half a cell along its normal, the cells behind it left out), on the
// side it faces (its winding's front). Its flux is albedo x area x irradiance, so a bounce
// carries at most the largest albedo times the light that the last one delivered.
// Only the front reflects: the back of a closed surface (a solid's face, either side of a wall
// built with thickness) faces into the solid, where the cells hold light the walls only partly
// stopped and the truth has none. Reflecting both sides made every such face send the light of
// the room beyond it back into that room a second time (the 8-bounce Cornell box at 1.21 of
// the truth, gallery-court at 1.64; front only: 0.86 and 0.78). An open surface lit from
// behind reflects nothing here, where the truth reflects its back's light.
#extension GL_GOOGLE_include_directive : require
#include "shared/albedo_code.h"
#include "shared/gpu_types.h"
#include "shared/lpv_gather_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_BLOCKER_GROUP) in;

layout(std140, set = 0, binding = GATHER_BOUNCE_LPV) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = GATHER_BOUNCE_BLOCKERS) readonly buffer Blockers { GpuBlocker blockers[]; };
layout(set = 0, binding = GATHER_BOUNCE_LIGHT_R, rgba32f) uniform readonly imageBuffer accumulated_r;
layout(set = 0, binding = GATHER_BOUNCE_LIGHT_G, rgba32f) uniform readonly imageBuffer accumulated_g;
layout(set = 0, binding = GATHER_BOUNCE_LIGHT_B, rgba32f) uniform readonly imageBuffer accumulated_b;
layout(set = 0, binding = GATHER_BOUNCE_WALLS, rgba32ui) uniform readonly uimageBuffer walls;
layout(std430, set = 0, binding = GATHER_BOUNCE_INJECTED) buffer Injected { int64_t injected[]; };  // 12 per cell: RGB x SH
layout(std430, set = 0, binding = GATHER_BOUNCE_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { LpvGatherBouncePush push; };
// The VPLs are added to the injected sums (a bounce follows), or only their flux is summed (the
// estimate of the bounces after the last: lpv_gather_tail.comp).
layout(constant_id = 1) const bool SPLAT = true;

#include "shared/lpv_grid_flux.glsl"
#include "shared/lpv_inject_vpl.glsl"
// The last bounce's light is an irradiance cube, read one surfel at a time (no lane shares
// its cells: neighbouring surfels lie on different triangles as often as not).
const uint CASCADES = 1u;
#include "shared/lpv_irradiance.glsl"

const float ON_THE_BORDER = 1e-3;  // cells

void main() {
  uint i = gl_GlobalInvocationID.x;
  bool valid = i < push.count;
  GpuBlocker b = blockers[min(i, max(push.count, 1u) - 1u)];
  vec3 n = b.normal.xyz;
  GpuLpvCascade g = lpv.cascades[push.cascade];
  // Its light is read half a cell along its normal, as the shading reads a surface's, where
  // that point lies in the cascade. A surfel of a surface that meets the grid's border at a
  // right angle has that point on the border itself, where float rounding alone would decide
  // (the Cornell box at 1 mm lost 1.1% of its all-bounce light so: Invariants.Scaling...): a
  // thousandth of a cell outside still counts; the lookup clamps to the border cells.
  // Its VPL, injection_offset along the normal, puts any share beyond the grid in the border
  // cells too (lpv_inject_vpl.glsl): none of the reflected flux is lost.
  vec3 q = lpv_grid_position(g, b.position.xyz + 0.5 * g.origin.w * n);
  bool inside = valid && lpv_inside_distance(g, q) >= -ON_THE_BORDER;
  vec3 flux = inside ? albedo_decode(b.normal.w) * b.position.w * cascade_irradiance(push.cascade, q, n) : vec3(0.0);
  add_grid_flux(flux, push.flux_record, lpv.scales.x);  // every invocation: a subgroup sum
  if (!SPLAT) return;
  ivec3 low;
  vec3 f;
  float values[SPLAT_VALUES];
  bool lit = flux.r + flux.g + flux.b > 0.0;
  vpl_splat(b.position.xyz, n, flux, low, f, values);  // its own inside test: not the one above
  // Past the located walls, as the injection adds the first bounce's VPLs.
  uvec2 factors = SPLAT_UNWEIGHED;
  if (LOCATED_WALLS) {
    float scale;
    factors = wall_splat_factors(push.cascade, vpl_grid_point(b.position.xyz, n), n, low, f, vpl_last_cell(), scale);
    for (uint k = 0u; k < SPLAT_VALUES; ++k) values[k] *= scale;
  }
  splat_subgroup(lit, low, f, values, vpl_last_cell(), lpv.scales.x, factors);  // by the whole subgroup
}
