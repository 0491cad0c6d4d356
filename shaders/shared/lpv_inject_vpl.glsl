// One VPL into a cascade: intensity I(w) = Phi / pi * max(0, <n, w>), whose integral over the
// sphere is Phi, moved injection_offset cells along its normal (against self-illumination)
// and added as SH to the 8 cells whose centres surround it with trilinear weights
// (shared/lpv_splat.glsl). Nearest-cell injection would make the grid jump by a whole cell
// when a VPL crosses a cell boundary: a light or camera moved by a hair would flicker. Shares
// that fall outside the grid go to its border cells, so no flux is lost. The lobe's directional
// terms are times lpv.transfer.y (LPV_SHARPENED_INJECTION with the sharpened transfer).
// Requires `lpv` (GpuLpv), `push.cascade` and an int64 `injected` buffer (12 per cell: RGB x
// SH) declared before the include.
#ifndef LPV_INJECT_VPL_GLSL
#define LPV_INJECT_VPL_GLSL

#define SPLAT_VALUES 12u
#define SPLAT_SUMS injected
uint splat_index(ivec3 cell) {
  return lpv_cell_index(uvec3(cell), lpv.cascades[push.cascade].dims.xyz) * SPLAT_VALUES;
}
#include "lpv_splat.glsl"

ivec3 vpl_last_cell() { return ivec3(lpv.cascades[push.cascade].dims.xyz) - 1; }

// Where a VPL is added, in cell units of the cascade: its position moved injection_offset cells
// along its normal.
vec3 vpl_grid_point(vec3 position, vec3 normal) {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  return lpv_grid_position(g, position + normal * (lpv.scales.w * g.origin.w));
}

// What a VPL adds: its SH per channel (RGB x 4), linear in its flux and in its normal's
// direction times the flux, so the values of VPLs added at one point are their sum.
void vpl_values(vec3 normal, vec3 flux, out float values[SPLAT_VALUES]) {
  for (uint c = 0u; c < 3u; ++c) {
    vec4 sh = sh_diffuse_emitter(normal, flux[c]) * vec4(1.0, vec3(lpv.transfer.y));
    for (uint k = 0u; k < 4u; ++k) values[c * 4u + k] = sh[k];
  }
}

// The splat of a point q (vpl_grid_point; lattice: cell centres): false when it lies outside
// the cascade.
bool vpl_lattice(vec3 q, out ivec3 low, out vec3 f) {
  splat_lattice(q - 0.5, low, f);
  return lpv_inside_distance(lpv.cascades[push.cascade], q) >= 0.0;
}

// The splat of a VPL: false when it lies outside the cascade.
bool vpl_splat(vec3 position, vec3 normal, vec3 flux, out ivec3 low, out vec3 f, out float values[SPLAT_VALUES]) {
  vpl_values(normal, flux, values);
  return vpl_lattice(vpl_grid_point(position, normal), low, f);
}

#endif
