#version 450
// After injection: the fixed-point sums become the float grid that propagation starts from
// (and the first term of the accumulated light), and the accumulators are cleared for the
// next cascade. Also sums the grid's flux for the statistics.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = 1) buffer Injected { int64_t injected[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Grids { vec4 grids[]; };  // 4 per cell: RGB SH, outgoing scale
layout(std430, set = 0, binding = 3) writeonly buffer Accumulated { vec4 accumulated[]; };
layout(std430, set = 0, binding = 4) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { uint cascade; uint stats_offset; } push;

#include "shared/lpv_grid_flux.glsl"

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  uvec3 cell = gl_GlobalInvocationID;
  bool in_grid = all(lessThan(cell, g.dims.xyz));
  vec3 flux = vec3(0.0);
  if (in_grid) {
    uint index = lpv_cell_index(cell, g.dims.xyz);
    vec4 sh[3];
    for (uint c = 0u; c < 3u; ++c) {
      for (uint k = 0u; k < 4u; ++k) {
        uint i = index * 12u + c * 4u + k;
        sh[c][k] = from_fixed(injected[i], 1.0 / lpv.scales.x);
        injected[i] = 0l;
      }
      grids[index * 4u + c] = sh[c];
      accumulated[(push.cascade * g.dims.w + index) * 3u + c] = sh[c];
      flux[c] = sh_flux(sh[c]);
    }
    grids[index * 4u + 3u] = vec4(lpv_outgoing_scale(sh[0]), lpv_outgoing_scale(sh[1]), lpv_outgoing_scale(sh[2]), 0.0);
  }
  add_group_flux(flux, push.stats_offset, lpv.scales.x);
}
