#version 450
// The gather's first step for a cascade (lpv_gather.comp reads what it writes): the pyramid of
// its sources (lpv_gather.h, "The sources, as a pyramid"). Level 0 holds each cell's injected
// light, its fixed-point sums converted once, not once per gathering cell; every level above
// sums the records of the one below, 2 x 2 x 2 of them into each of its blocks, in a fixed
// order, so the result does not depend on the order the invocations run in. One work group,
// which waits for each level before the next.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_gather_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_gather.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GATHER_SOURCES_GROUP) in;

layout(std140, set = 0, binding = GATHER_SOURCES_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = GATHER_SOURCES_INJECTED, rgba32ui) uniform readonly uimageBuffer injected;  // 6 texels of 2 sums per cell
layout(std430, set = 0, binding = GATHER_SOURCES_STORE) coherent buffer Sources { u64vec2 sources[]; };
layout(push_constant) uniform Push { LpvGatherPush push; };

vec4 texel_at(int texel) { return texel_value(sources[texel]); }

void store_record(int record, vec4 sh, vec3 flux, vec3 centre) {
  sources[LPV_GATHER_RECORD_TEXELS * record] = texel_bits(sh);
  sources[LPV_GATHER_RECORD_TEXELS * record + 1] = texel_bits(vec4(flux, 0.0));
  sources[LPV_GATHER_RECORD_TEXELS * record + 2] = texel_bits(vec4(centre, 0.0));
}

void store_cell(int cell, ivec3 dims) {
  vec4 sh[3];
  for (int c = 0; c < 3; ++c)
    sh[c] = from_fixed(fixed_pair(imageLoad(injected, 6 * cell + 2 * c)), fixed_pair(imageLoad(injected, 6 * cell + 2 * c + 1)),
                       1.0 / lpv.scales.x);
  ivec3 at = ivec3(cell % dims.x, (cell / dims.x) % dims.y, cell / (dims.x * dims.y));
  // Each channel's flux / pi: 4 c0 s0 (lpv_sh.h: flux = 4 pi c0 s0).
  vec4 summed = sh[0] + sh[1] + sh[2];
  vec4 emitter = lpv_gather_emitter(summed, lpv.transfer.y);
  store_record(cell, summed, 4.0 * SH_C0 * vec3(sh[0].x, sh[1].x, sh[2].x), lpv_gather_surface(vec3(at), emitter, lpv.scales.w));
}

void store_block(int block, int level, ivec3 dims) {
  ivec3 level_dims = lpv_gather_level_dims(dims, level);
  ivec3 below = lpv_gather_level_dims(dims, level - 1);
  int first_below = lpv_gather_level_first(dims, level - 1);
  ivec3 at = ivec3(block % level_dims.x, (block / level_dims.x) % level_dims.y, block / (level_dims.x * level_dims.y));
  vec4 sh = vec4(0.0);
  vec3 flux = vec3(0.0);
  vec3 weighted = vec3(0.0);
  float weight = 0.0;
  for (int z = 2 * at.z; z < min(2 * at.z + 2, below.z); ++z)
    for (int y = 2 * at.y; y < min(2 * at.y + 2, below.y); ++y)
      for (int x = 2 * at.x; x < min(2 * at.x + 2, below.x); ++x) {
        int child = LPV_GATHER_RECORD_TEXELS * (first_below + x + below.x * (y + below.y * z));
        vec3 child_flux = texel_at(child + 1).xyz;
        float w = child_flux.x + child_flux.y + child_flux.z;
        if (!(w > 0.0)) continue;
        sh += texel_at(child);
        flux += child_flux;
        weighted += w * texel_at(child + 2).xyz;
        weight += w;
      }
  store_record(lpv_gather_level_first(dims, level) + block, sh, flux, weight > 0.0 ? weighted / weight : vec3(0.0));
}

void main() {
  ivec3 dims = ivec3(lpv.cascades[push.cascade].dims.xyz);
  int group = int(LPV_GATHER_SOURCES_GROUP);
  int cells = dims.x * dims.y * dims.z;
  for (int cell = int(gl_LocalInvocationID.x); cell < cells; cell += group) store_cell(cell, dims);
  int levels = lpv_gather_levels(dims);
  for (int level = 1; level < levels; ++level) {
    memoryBarrierBuffer();
    barrier();
    int blocks = lpv_gather_level_blocks(dims, level);
    for (int block = int(gl_LocalInvocationID.x); block < blocks; block += group) store_block(block, level, dims);
  }
}
