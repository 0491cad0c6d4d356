#version 450
// Injection of emissive surfaces: each surfel (renderer/lpv/emitter_surfels.hpp) is a VPL of
// its emitted flux, added to the same fixed-point sums as the RSM's VPLs.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_inject_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_EMITTER_GROUP) in;

layout(std140, set = 0, binding = INJECT_EMITTERS_LPV) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = INJECT_EMITTERS_EMITTERS) readonly buffer Emitters { GpuEmitter emitters[]; };
layout(std430, set = 0, binding = INJECT_EMITTERS_INJECTED) buffer Injected { int64_t injected[]; };  // 12 per cell: RGB x SH
layout(std430, set = 0, binding = INJECT_EMITTERS_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { LpvInjectEmittersPush push; };

#include "shared/lpv_grid_flux.glsl"
#include "shared/lpv_inject_vpl.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  bool in_range = i < push.count;
  vec3 flux = in_range ? emitters[i].flux.rgb : vec3(0.0);
  add_grid_flux(flux, push.stats_record, lpv.scales.x);  // every invocation: a subgroup sum
  ivec3 low;
  vec3 f;
  float values[SPLAT_VALUES];
  if (in_range && vpl_splat(emitters[i].position.xyz, emitters[i].normal.xyz, flux, low, f, values))
    splat_point(low, f, values, vpl_last_cell(), lpv.scales.x, SPLAT_UNWEIGHED);
}
