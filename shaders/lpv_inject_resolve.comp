#version 450
// After injection: the fixed-point sums become the float grid that propagation starts from
// (and the first term of the accumulated light). Also sums the grid's flux for the statistics.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_inject_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = INJECT_RESOLVE_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = INJECT_RESOLVE_INJECTED, rgba32ui) uniform readonly uimageBuffer injected;  // 6 texels of 2 sums per cell
layout(std430, set = 0, binding = INJECT_RESOLVE_GRIDS) writeonly buffer Grids { u64vec2 grids[]; };
layout(std430, set = 0, binding = INJECT_RESOLVE_ACCUMULATED_R) writeonly buffer AccumulatedR { u64vec2 accumulated_r[]; };
layout(std430, set = 0, binding = INJECT_RESOLVE_ACCUMULATED_G) writeonly buffer AccumulatedG { u64vec2 accumulated_g[]; };
layout(std430, set = 0, binding = INJECT_RESOLVE_ACCUMULATED_B) writeonly buffer AccumulatedB { u64vec2 accumulated_b[]; };
layout(std430, set = 0, binding = INJECT_RESOLVE_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { LpvInjectPush push; };

#include "shared/lpv_grid_flux.glsl"

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  vec3 flux = vec3(0.0);
  if (all(lessThan(cell, ivec3(g.dims.xyz)))) {
    int texel = 6 * int(lpv_cell_index(uvec3(cell), g.dims.xyz));
    vec4 sh[3];
    for (int c = 0; c < 3; ++c) {
      sh[c] = from_fixed(fixed_pair(imageLoad(injected, texel + 2 * c)), fixed_pair(imageLoad(injected, texel + 2 * c + 1)),
                         1.0 / lpv.scales.x);
      vec4 sent = lpv_sender_form(sh[c]);
      grids[lpv_grid_texel(cell, c, 0u, g.dims.xyz)] = texel_bits(sent * lpv_sender_outgoing_scale(sent));
      flux[c] = sh_flux(sh[c]);
    }
    int accumulated = lpv_accumulated_texel(cell, push.cascade, g.dims.xyz);
    accumulated_r[accumulated] = texel_bits(sh[0]);
    accumulated_g[accumulated] = texel_bits(sh[1]);
    accumulated_b[accumulated] = texel_bits(sh[2]);
  }
  add_grid_flux(flux, push.stats_record, lpv.scales.x);
}
