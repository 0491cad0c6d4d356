// One VPL into a cascade: intensity I(w) = Phi / pi * max(0, <n, w>), whose integral over the
// sphere is Phi, moved injection_offset cells along its normal (against self-illumination)
// and added as SH, in fixed point (deterministic in any order), to the 8 cells whose centres
// surround it with trilinear weights. Nearest-cell injection would make the grid jump by a
// whole cell when a VPL crosses a cell boundary: a light or camera moved by a hair would
// flicker. Shares that fall outside the grid go to its border cells, so no flux is lost.
// Requires `lpv` (GpuLpv) and an int64 `injected` buffer declared before the include.
#ifndef LPV_INJECT_VPL_GLSL
#define LPV_INJECT_VPL_GLSL

// lpv.injection "nearest": each VPL into the one cell it lands in (the paper's way; cheaper,
// but not continuous). A specialization constant, so each pipeline runs one of the two.
layout(constant_id = 0) const bool TRILINEAR_INJECTION = true;

void inject_vpl(GpuLpvCascade g, vec3 position, vec3 normal, vec3 flux) {
  vec3 q = lpv_grid_position(g, position + normal * (lpv.scales.w * g.origin.w));
  if (lpv_inside_distance(g, q) < 0.0) return;
  ivec3 last = ivec3(g.dims.xyz) - 1;
  vec3 t = q - 0.5;  // in units of cell centres
  ivec3 low = TRILINEAR_INJECTION ? ivec3(floor(t)) : min(ivec3(q), last);
  vec3 f = t - vec3(low);
  vec4 lobe = sh_cosine_lobe(normal) / LPV_PI;
  for (uint corner = 0u; corner < (TRILINEAR_INJECTION ? 8u : 1u); ++corner) {
    ivec3 o = ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    float w = TRILINEAR_INJECTION ? w3.x * w3.y * w3.z : 1.0;
    if (w == 0.0) continue;
    uint base = lpv_cell_index(uvec3(clamp(low + o, ivec3(0), last)), g.dims.xyz) * 12u;
    for (uint c = 0u; c < 3u; ++c) {
      if (flux[c] == 0.0) continue;
      vec4 sh = lobe * (flux[c] * w);
      for (uint k = 0u; k < 4u; ++k) atomicAdd(injected[base + c * 4u + k], to_fixed(sh[k], lpv.scales.x));
    }
  }
}

#endif
