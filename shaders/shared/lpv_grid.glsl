// Addressing of the LPV grids, for the LPV passes and the shading. An SH grid cell is one vec4
// per colour channel (see lpv_sh.h for the basis); buffers hold cells in x-fastest order
// (renderer/lpv/lpv_volumes.hpp).
#ifndef LPV_GRID_GLSL
#define LPV_GRID_GLSL

uint lpv_cell_index(uvec3 cell, uvec3 dims) { return cell.x + dims.x * (cell.y + dims.y * cell.z); }

// Position in cell units of cascade g (0 at the minimum corner, dims at the maximum).
vec3 lpv_grid_position(GpuLpvCascade g, vec3 p) { return (p - g.origin.xyz) / g.origin.w; }

// How far q (cell units) is inside the grid: negative outside, in cells.
float lpv_inside_distance(GpuLpvCascade g, vec3 q) {
  vec3 to_max = vec3(g.dims.xyz) - q;
  return min(min(min(q.x, q.y), q.z), min(min(to_max.x, to_max.y), to_max.z));
}

// Texel of the propagation grids (LpvVolumes::grids): channel k of a cell in grid `which`
// (0 or 1).
int lpv_grid_texel(ivec3 cell, int k, uint which, uvec3 dims) {
  return 3 * int(lpv_cell_index(uvec3(cell), dims) + which * dims.x * dims.y * dims.z) + k;
}

// Texel of a cascade's cell in the accumulated buffers (LpvVolumes::accumulated).
int lpv_accumulated_texel(ivec3 cell, uint cascade, uvec3 dims) {
  return int(lpv_cell_index(uvec3(cell), dims) + cascade * dims.x * dims.y * dims.z);
}

// Texels of the geometry volume's faces (LpvVolumes::faces): the blocking SH on face k = 0,
// 1, 2 (+X, +Y, +Z) of a cell, and in a second block the spread of the blockers' normals
// there (lpv_closed_blocking), so that the blocking SH of neighbouring cells share cache
// lines; and in LpvVolumes::face_albedo the blockers' albedo there (bounces only).
int lpv_face_texel(ivec3 cell, int k, uvec3 dims) { return 3 * int(lpv_cell_index(uvec3(cell), dims)) + k; }
int lpv_face_spread_texel(ivec3 cell, int k, uvec3 dims) {
  return 3 * int(dims.x * dims.y * dims.z + lpv_cell_index(uvec3(cell), dims)) + k;
}
int lpv_face_albedo_texel(ivec3 cell, int k, uvec3 dims) { return 3 * int(lpv_cell_index(uvec3(cell), dims)) + k; }
int lpv_face_cover_texel(ivec3 cell, int k, uvec3 dims) { return 3 * int(lpv_cell_index(uvec3(cell), dims)) + k; }

#endif
