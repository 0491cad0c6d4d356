#version 450
// Geometry volume, step 2: each cell corner keeps the stronger of its two sources (RSM or
// camera surfels, which may see the same wall), as floats for the face pass.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = 1) readonly buffer CornerSums { int64_t corner_sums[]; };
layout(set = 0, binding = 2, rgba32f) uniform writeonly image3D corners;
layout(push_constant) uniform Push { uint cascade; } push;
// The blockers' albedo serves bounces only: without them its corners are neither read nor written.
layout(constant_id = 0) const bool BOUNCES = true;

void main() {
  uvec3 corner_dims = lpv.cascades[push.cascade].dims.xyz + 1u;
  uvec3 corner = gl_GlobalInvocationID;
  if (any(greaterThanEqual(corner, corner_dims))) return;
  float one_per_unit = 1.0 / lpv.scales.y;
  uint index = lpv_cell_index(corner, corner_dims);
  vec4 sh = vec4(0.0);
  vec4 albedo = vec4(0.0);
  for (uint source = 0u; source < LPV_GV_SOURCES; ++source) {
    uint base = (index * LPV_GV_SOURCES + source) * LPV_GV_WORDS;
    float potential = from_fixed(corner_sums[base], one_per_unit);
    if (potential <= sh.x) continue;
    for (uint k = 0u; k < 4u; ++k) {
      sh[k] = from_fixed(corner_sums[base + k], one_per_unit);
      if (BOUNCES) albedo[k] = from_fixed(corner_sums[base + 4u + k], one_per_unit);
    }
  }
  imageStore(corners, ivec3(2u * corner.x, corner.yz), sh);
  if (BOUNCES) imageStore(corners, ivec3(2u * corner.x + 1u, corner.yz), albedo);
}
