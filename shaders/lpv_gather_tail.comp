#version 450
// The bounces after the last one gathered, estimated ("bounces": "all"; lpv_gather.h,
// lpv_bounce_tail_factor; docs/lpv.md, "Bounces"): each cell's last gathered cube, times
// r / (1 - r) per channel, added to its accumulated light. r is the flux the last bounce's light
// reflects (lpv_gather_bounce.comp, which summed it) over the flux it was gathered from; every
// invocation reads both from the flux statistics, so the estimate needs no trip to the host.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_gather_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_gather.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = GATHER_TAIL_LPV) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = GATHER_TAIL_FLUX_STATS) readonly buffer FluxStats { int64_t flux_stats[]; };
layout(set = 0, binding = GATHER_TAIL_LIGHT_R, rgba32f) uniform readonly imageBuffer light_r;
layout(set = 0, binding = GATHER_TAIL_LIGHT_G, rgba32f) uniform readonly imageBuffer light_g;
layout(set = 0, binding = GATHER_TAIL_LIGHT_B, rgba32f) uniform readonly imageBuffer light_b;
layout(std430, set = 0, binding = GATHER_TAIL_ACCUMULATED_R) buffer AccumulatedR { u64vec2 accumulated_r[]; };
layout(std430, set = 0, binding = GATHER_TAIL_ACCUMULATED_G) buffer AccumulatedG { u64vec2 accumulated_g[]; };
layout(std430, set = 0, binding = GATHER_TAIL_ACCUMULATED_B) buffer AccumulatedB { u64vec2 accumulated_b[]; };
layout(push_constant) uniform Push { LpvGatherTailPush push; };

// A record's flux in channel c, in the sums' units (the ratio needs no conversion).
float record_flux(uint record, uint c) {
  int64_t sum = 0l;
  for (uint slot = 0u; slot < LPV_FLUX_SLOTS; ++slot) sum += flux_stats[(record * LPV_FLUX_SLOTS + slot) * LPV_FLUX_SLOT_INT64S + c];
  return float(sum);
}

void main() {
  uvec3 dims = lpv.cascades[push.cascade].dims.xyz;
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(cell, ivec3(dims)))) return;
  vec3 factor;
  for (uint c = 0u; c < 3u; ++c)
    factor[c] = lpv_bounce_tail_factor(record_flux(push.gathered_record, c), record_flux(push.reflected_record, c));
  int first = 2 * lpv_accumulated_texel(cell, push.cascade, dims);
  for (int k = 0; k < 2; ++k) {
    accumulated_r[first + k] = texel_bits(texel_value(accumulated_r[first + k]) + factor.r * imageLoad(light_r, first + k));
    accumulated_g[first + k] = texel_bits(texel_value(accumulated_g[first + k]) + factor.g * imageLoad(light_g, first + k));
    accumulated_b[first + k] = texel_bits(texel_value(accumulated_b[first + k]) + factor.b * imageLoad(light_b, first + k));
  }
}
