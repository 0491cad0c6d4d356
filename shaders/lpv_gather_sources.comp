#version 450
// The gather's first step for a cascade (lpv_gather.comp reads what it writes): the injected
// cells that hold light, in cell order, each with what it emits, so that every gathering cell
// passes over the empty ones and converts the fixed-point sums once, not once per cell. One
// work group: each invocation counts the lit cells of its stretch of cells, the counts become
// offsets, and each writes its stretch's records at its offset, so the list's order is the
// cells' order whatever order the invocations run in.
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
layout(std430, set = 0, binding = GATHER_SOURCES_STORE) writeonly buffer Sources { u64vec2 sources[]; };
layout(push_constant) uniform Push { LpvGatherPush push; };

shared uint offsets[LPV_GATHER_SOURCES_GROUP];

bool lit(int cell) {
  uvec4 r = imageLoad(injected, 6 * cell), g = imageLoad(injected, 6 * cell + 2), b = imageLoad(injected, 6 * cell + 4);
  return (r.x | r.y | g.x | g.y | b.x | b.y) != 0u;  // a constant term that is not 0
}

void main() {
  uvec3 dims = lpv.cascades[push.cascade].dims.xyz;
  int cells = int(dims.x * dims.y * dims.z);
  int stretch = (cells + int(LPV_GATHER_SOURCES_GROUP) - 1) / int(LPV_GATHER_SOURCES_GROUP);
  int first = int(gl_LocalInvocationID.x) * stretch;
  int last = min(first + stretch, cells);
  uint count = 0u;
  for (int cell = first; cell < last; ++cell) count += lit(cell) ? 1u : 0u;
  offsets[gl_LocalInvocationID.x] = count;
  barrier();
  if (gl_LocalInvocationID.x == 0u) {
    uint total = 0u;
    for (uint i = 0u; i < LPV_GATHER_SOURCES_GROUP; ++i) {
      uint n = offsets[i];
      offsets[i] = total;
      total += n;
    }
    sources[0] = u64vec2(uint64_t(total), uint64_t(0));
  }
  barrier();
  float one_per_unit = 1.0 / lpv.scales.x;
  uint at = offsets[gl_LocalInvocationID.x];
  for (int cell = first; cell < last; ++cell) {
    if (!lit(cell)) continue;
    vec4 sh[3];
    for (int c = 0; c < 3; ++c)
      sh[c] = from_fixed(fixed_pair(imageLoad(injected, 6 * cell + 2 * c)), fixed_pair(imageLoad(injected, 6 * cell + 2 * c + 1)),
                         one_per_unit);
    // Each channel's flux / pi: 4 c0 s0 (lpv_sh.h: flux = 4 pi c0 s0); the cell's index in w.
    sources[1 + 2 * at] = texel_bits(lpv_gather_emitter(sh[0] + sh[1] + sh[2], lpv.transfer.y));
    sources[2 + 2 * at] = texel_bits(vec4(4.0 * SH_C0 * vec3(sh[0].x, sh[1].x, sh[2].x), float(cell)));
    ++at;
  }
}
