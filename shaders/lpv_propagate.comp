#version 450
// One propagation iteration, as a gather: each cell collects the light its 6 neighbours send
// through its faces. A neighbour at -a (a = one of the 6 axes) sends through 5 faces of this
// cell: the far face, in direction a with solid angle 4 asin(1/10), and the 4 side faces, in
// the direction of their centres (2a + s)/sqrt(5) with solid angle 2 atan(3/sqrt(11)) - pi/3.
// The flux through a face, Omega * I(w) (no 1/(4 pi), annotations 6.2), enters this cell as a
// cosine lobe along the face's normal, Phi/pi * max(0, <n, w>), which keeps that flux
// (annotations 6.3). Negative face fluxes are handled by lpv_outgoing_scale (see lpv_sh.h).
// From the second iteration on, the geometry volume on the face shared with the neighbour
// blocks part of the light (none in the first, where the injecting surface would block itself).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(std430, set = 0, binding = 1) buffer Grids { vec4 grids[]; };  // 2 grids of 4 vec4 per cell
layout(std430, set = 0, binding = 2) buffer Accumulated { vec4 accumulated[]; };
layout(std430, set = 0, binding = 3) readonly buffer Faces { vec4 faces[]; };
layout(std430, set = 0, binding = 4) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { uint cascade; uint stats_offset; uint iteration; } push;

#include "shared/lpv_grid_flux.glsl"

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  ivec3 dims = ivec3(g.dims.xyz);
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  bool in_grid = all(lessThan(cell, dims));
  uint cells = g.dims.w;
  uint source_base = ((push.iteration + 1u) & 1u) * cells;  // iteration 1 reads grid 0
  uint target_base = (push.iteration & 1u) * cells;
  bool occluded = (lpv.info.z & LPV_FLAG_OCCLUSION) != 0u && push.iteration >= 2u;
  bool bounces = occluded && (lpv.info.z & LPV_FLAG_BOUNCES) != 0u;

  vec4 gathered[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int i = 0; in_grid && i < 6; ++i) {
    vec3 ahead = lpv_axis(i);
    ivec3 neighbour = cell - ivec3(ahead);
    if (any(lessThan(neighbour, ivec3(0))) || any(greaterThanEqual(neighbour, dims))) continue;
    uint from = (source_base + lpv_cell_index(uvec3(neighbour), g.dims.xyz)) * 4u;
    vec4 sh_r = grids[from], sh_g = grids[from + 1u], sh_b = grids[from + 2u];
    vec3 scale = grids[from + 3u].xyz;
    if (scale == vec3(0.0)) continue;

    vec4 blocking = vec4(0.0);
    vec3 albedo = vec3(0.0);
    vec3 reflect_normal = vec3(0.0);
    if (occluded) {
      // The face between the two cells belongs to the lower one, on the axis of travel.
      uint axis = uint(i / 2);
      uint lower = lpv_cell_index(uvec3(min(cell, neighbour)), g.dims.xyz);
      blocking = faces[lower * 6u + axis];
      albedo = faces[lower * 6u + 3u + axis].rgb;
      vec3 mean_normal = vec3(-blocking.w, -blocking.y, blocking.z);  // linear SH part -> direction
      reflect_normal = dot(mean_normal, mean_normal) > 0.0 ? normalize(mean_normal) : -ahead;
    }

    for (int f = 0; f < 5; ++f) {
      // f = 0: the far face; f = 1..4: the side faces, on the 4 axes across `ahead`.
      int side_axis = f == 0 ? i : (2 * ((i / 2 + 1 + (f - 1) / 2) % 3) + (f - 1) % 2);
      vec3 normal = lpv_axis(side_axis);
      vec3 w = f == 0 ? ahead : lpv_face_direction(ahead, normal);
      float solid_angle = f == 0 ? LPV_FAR_FACE_SOLID_ANGLE : LPV_SIDE_FACE_SOLID_ANGLE;
      vec4 basis = sh_basis(w);
      vec3 flux = solid_angle * scale * max(vec3(dot(sh_r, basis), dot(sh_g, basis), dot(sh_b, basis)), vec3(0.0));
      if (occluded) {
        float blocked = clamp(sh_evaluate(blocking, -w), 0.0, 1.0);
        if (bounces) {
          vec3 reflected = flux * blocked * albedo;
          vec4 lobe = sh_cosine_lobe(reflect_normal) / LPV_PI;
          gathered[0] += reflected.r * lobe;
          gathered[1] += reflected.g * lobe;
          gathered[2] += reflected.b * lobe;
        }
        flux *= 1.0 - blocked;
      }
      vec4 lobe = sh_cosine_lobe(normal) / LPV_PI;
      gathered[0] += flux.r * lobe;
      gathered[1] += flux.g * lobe;
      gathered[2] += flux.b * lobe;
    }
  }

  vec3 flux = vec3(0.0);
  if (in_grid) {
    uint index = lpv_cell_index(uvec3(cell), g.dims.xyz);
    uint to = (target_base + index) * 4u;
    uint acc = (push.cascade * cells + index) * 3u;
    for (uint c = 0u; c < 3u; ++c) {
      grids[to + c] = gathered[c];
      accumulated[acc + c] += gathered[c];
      flux[c] = sh_flux(gathered[c]);
    }
    grids[to + 3u] = vec4(lpv_outgoing_scale(gathered[0]), lpv_outgoing_scale(gathered[1]),
                          lpv_outgoing_scale(gathered[2]), 0.0);
  }
  add_group_flux(flux, push.stats_offset, lpv.scales.x);
}
