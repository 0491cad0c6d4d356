#version 450
// Geometry volume, step 2: for each cell, the blocking potential on its +X, +Y and +Z faces:
// the mean of the face's four corners, where each corner takes the stronger of its two
// sources. Propagation between two neighbouring cells reads the face they share. Also the
// blockers' mean albedo per face, for the light they reflect (bounces).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = 1) readonly buffer Corners { int64_t corners[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Faces { vec4 faces[]; };  // 6 per cell: 3 SH, 3 albedo
layout(push_constant) uniform Push { uint cascade; } push;

// The stronger source of one corner: its blocking SH and albedo-weighted sum (w = weight).
void corner_blocking(uvec3 corner, uvec3 corner_dims, out vec4 sh, out vec4 albedo) {
  float one_per_unit = 1.0 / lpv.scales.y;
  sh = vec4(0.0);
  albedo = vec4(0.0);
  uint index = lpv_cell_index(corner, corner_dims);
  for (uint source = 0u; source < LPV_GV_SOURCES; ++source) {
    uint base = (index * LPV_GV_SOURCES + source) * LPV_GV_WORDS;
    vec4 s = vec4(from_fixed(corners[base], one_per_unit), from_fixed(corners[base + 1u], one_per_unit),
                  from_fixed(corners[base + 2u], one_per_unit), from_fixed(corners[base + 3u], one_per_unit));
    if (s.x <= sh.x) continue;
    sh = s;
    albedo = vec4(from_fixed(corners[base + 4u], one_per_unit), from_fixed(corners[base + 5u], one_per_unit),
                  from_fixed(corners[base + 6u], one_per_unit), from_fixed(corners[base + 7u], one_per_unit));
  }
}

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  uvec3 cell = gl_GlobalInvocationID;
  if (any(greaterThanEqual(cell, g.dims.xyz))) return;
  uvec3 corner_dims = g.dims.xyz + 1u;
  uint index = lpv_cell_index(cell, g.dims.xyz);
  for (uint axis = 0u; axis < 3u; ++axis) {
    // The face at +axis: its corners have cell[axis] + 1 on the axis and both values on the others.
    uint u = (axis + 1u) % 3u;
    uint v = (axis + 2u) % 3u;
    vec4 sh = vec4(0.0);
    vec4 albedo = vec4(0.0);
    for (uint k = 0u; k < 4u; ++k) {
      uvec3 corner = cell;
      corner[axis] += 1u;
      corner[u] += k & 1u;
      corner[v] += k >> 1u;
      vec4 corner_sh, corner_albedo;
      corner_blocking(corner, corner_dims, corner_sh, corner_albedo);
      sh += 0.25 * corner_sh;
      albedo += corner_albedo;
    }
    faces[index * 6u + axis] = sh;
    faces[index * 6u + 3u + axis] = vec4(albedo.w > 0.0 ? albedo.rgb / albedo.w : vec3(0.0), 0.0);
  }
}
