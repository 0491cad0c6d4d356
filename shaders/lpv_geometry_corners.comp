#version 450
// Geometry volume, step 2: each cell corner keeps the strongest of its sources (RSM, camera
// or scene surfels, which may hold the same wall), as floats for the face pass.
#extension GL_GOOGLE_include_directive : require
#include "shared/geometry_volume_interface.h"
#include "shared/gpu_types.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = GEOMETRY_CORNERS_LPV) uniform Lpv { GpuLpv lpv; };
// lpv_gv_corner_words(BOUNCES) sums per corner and slot, `slots` a corner (gpu_types.h), two a texel.
// Written: LPV_GV_CORNER_TEXELS texels per corner.
layout(set = 0, binding = GEOMETRY_CORNERS_SUMS, rgba32ui) uniform readonly uimageBuffer corner_sums;
layout(std430, set = 0, binding = GEOMETRY_CORNERS_CORNERS) writeonly buffer Corners { u64vec2 corners[]; };
layout(push_constant) uniform Push { GeometryCornersPush push; };
// The blockers' albedo serves bounces only: without them its corners are neither read nor written.
layout(constant_id = 0) const bool BOUNCES = true;

void main() {
  uvec3 corner_dims = lpv.cascades[push.cascade].dims.xyz + 1u;
  uvec3 corner = gl_GlobalInvocationID;
  if (any(greaterThanEqual(corner, corner_dims))) return;
  float one_per_unit = 1.0 / lpv.scales.y;
  uint index = lpv_cell_index(corner, corner_dims);
  vec4 sh = vec4(0.0);
  vec4 spread = vec4(0.0);
  vec4 albedo = vec4(0.0);
  for (uint slot = 0u; slot < push.slots; ++slot) {
    int base = int((index * push.slots + slot) * lpv_gv_corner_words(BOUNCES) / 2u);
    vec4 source_sh = from_fixed(fixed_pair(imageLoad(corner_sums, base)), fixed_pair(imageLoad(corner_sums, base + 1)),
                                one_per_unit);
    if (source_sh.x <= sh.x) continue;
    sh = source_sh;
    const int m = int(LPV_GV_SPREAD / 2u);
    spread = from_fixed(fixed_pair(imageLoad(corner_sums, base + m)), fixed_pair(imageLoad(corner_sums, base + m + 1)),
                        one_per_unit);
    const int a = int(LPV_GV_ALBEDO / 2u);
    if (BOUNCES)
      albedo = from_fixed(fixed_pair(imageLoad(corner_sums, base + a)), fixed_pair(imageLoad(corner_sums, base + a + 1)),
                          one_per_unit);
  }
  uint texel = LPV_GV_CORNER_TEXELS * index;
  corners[texel] = texel_bits(sh);
  corners[texel + 1u] = texel_bits(spread);
  if (BOUNCES) corners[texel + 2u] = texel_bits(albedo);
}
