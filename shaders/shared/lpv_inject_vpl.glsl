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

// The splat of a VPL (lattice: cell centres): false when it lies outside the cascade.
bool vpl_splat(vec3 position, vec3 normal, vec3 flux, out ivec3 low, out vec3 f, out float values[SPLAT_VALUES]) {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  vec3 q = lpv_grid_position(g, position + normal * (lpv.scales.w * g.origin.w));
  for (uint c = 0u; c < 3u; ++c) {
    vec4 sh = sh_diffuse_emitter(normal, flux[c]) * vec4(1.0, vec3(lpv.transfer.y));
    for (uint k = 0u; k < 4u; ++k) values[c * 4u + k] = sh[k];
  }
  splat_lattice(q - 0.5, low, f);  // lattice: cell centres
  return lpv_inside_distance(g, q) >= 0.0;
}

#endif
