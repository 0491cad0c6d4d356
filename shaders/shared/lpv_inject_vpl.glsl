// One VPL into a cascade: intensity I(w) = Phi / pi * max(0, <n, w>), whose integral over the
// sphere is Phi, moved injection_offset cells along its normal (against self-illumination)
// and added as SH into the cell it lands in, in fixed point (deterministic in any order).
// Requires `lpv` (GpuLpv) and an int64 `injected` buffer declared before the include.
#ifndef LPV_INJECT_VPL_GLSL
#define LPV_INJECT_VPL_GLSL

void inject_vpl(GpuLpvCascade g, vec3 position, vec3 normal, vec3 flux) {
  vec3 q = lpv_grid_position(g, position + normal * (lpv.scales.w * g.origin.w));
  if (lpv_inside_distance(g, q) < 0.0) return;
  uvec3 cell = min(uvec3(q), g.dims.xyz - 1u);
  uint base = lpv_cell_index(cell, g.dims.xyz) * 12u;
  vec4 lobe = sh_cosine_lobe(normal) / LPV_PI;
  for (uint c = 0u; c < 3u; ++c) {
    if (flux[c] == 0.0) continue;
    vec4 sh = lobe * flux[c];
    for (uint k = 0u; k < 4u; ++k) atomicAdd(injected[base + c * 4u + k], to_fixed(sh[k], lpv.scales.x));
  }
}

#endif
