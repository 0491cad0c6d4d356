// The located walls (lpv_walls.h) as the passes that read them use them: how much of the light
// between a point and one of the 8 cell centres around it the walls between them let through.
// The injection weighs a VPL's 8 cells by it, the shading's lookup a surface's.
// Requires `walls` (uimageBuffer, rgba32ui: LpvVolumes::walls) and lpv_grid.glsl before the
// include.
#ifndef LPV_WALLS_GLSL
#define LPV_WALLS_GLSL

#include "lpv_walls.h"

// The light between q (cell units of cascade c), a point of a surface facing n, and the centre of
// `cell`, one of the 8 around it from `low` (clamped to the grid, whose last cell is `last`),
// that the located walls let through (lpv_walls_let_through). The walls across axis k between them lie about the plane low_k + 1, and the cell on
// its low side at `cell`'s place across the axis holds them; an axis along which both of the
// pair are one cell (the grid's border) has none.
float wall_visibility(uint c, ivec3 low, ivec3 cell, vec3 q, vec3 n, ivec3 last) {
  float through = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (low[k] < 0 || low[k] >= last[k]) continue;
    ivec3 holder = cell;
    holder[k] = low[k];
    uint packed = imageLoad(walls, lpv_accumulated_texel(holder, c, uvec3(last + 1)))[k];
    through *= lpv_walls_let_through(lpv_walls_from_unorm(unpackUnorm4x8(packed)), float(low[k] + 1), q[k],
                                     float(cell[k]) + 0.5, n[k]);
  }
  return through;
}

// A point's splat at q (cell units; lattice `low` + `f` on the cell centres), of a surface
// facing n, weighed by the walls
// between it and each of its 8 cells: the factors lpv_splat.glsl takes (8 unorm bytes), and
// the scale on its values that keeps their sum, all of it going to the cells it sees (faded
// where it sees less than LPV_WALL_LEAST_WEIGHT of them, as the lookup is).
uvec2 wall_splat_factors(uint c, vec3 q, vec3 n, ivec3 low, vec3 f, ivec3 last, out float scale) {
  uvec2 factors = uvec2(0u);
  float seen = 0.0;
  for (uint corner = 0u; corner < 8u; ++corner) {
    ivec3 o = ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
    uint byte = uint(round(255.0 * wall_visibility(c, low, clamp(low + o, ivec3(0), last), q, n, last)));
    factors[corner >> 2u] |= byte << (8u * (corner & 3u));
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    seen += w3.x * w3.y * w3.z * float(byte) / 255.0;
  }
  scale = 1.0 / max(seen, LPV_WALL_LEAST_WEIGHT);
  return factors;
}

#endif
