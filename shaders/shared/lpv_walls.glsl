// The located walls (lpv_walls.h) as the passes that read them use them: how much of the light
// between a point and one of the 8 cell centres around it the walls between them let through.
// The injection weighs a VPL's 8 cells by it, the shading's lookup a surface's.
// Requires `walls` (uimageBuffer, rgba32ui: LpvVolumes::walls) and lpv_grid.glsl before the
// include.
#ifndef LPV_WALLS_GLSL
#define LPV_WALLS_GLSL

#include "lpv_walls.h"

// The located walls' words (an axis each, and w: the centre inside a thin solid) of the 8 cells
// around a point from `low`: corner k is the cell low + (k & 1, k >> 1 & 1, k >> 2), clamped to
// the grid, whose last cell is `last`.
void load_walls(uint c, ivec3 low, ivec3 last, out uvec4 words[8]) {
  for (uint corner = 0u; corner < 8u; ++corner) {
    ivec3 cell = clamp(low + ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u), ivec3(0), last);
    words[corner] = imageLoad(walls, lpv_accumulated_texel(cell, c, uvec3(last + 1)));
  }
}

// The bytes of a walls word that hold the covers (lpv_walls_to_unorm's y and w): none set, no
// wall about the face.
const uint WALL_COVER_BYTES = 0xff00ff00u;

// The weights of a pair of cells along an axis, on either side of the plane `plane` (cell
// units along it), times what the walls about that plane (their word, held by the pair's low
// cell) let through from q (its coordinate along the axis) to each one's centre. A face without
// walls costs one test, a face with only the surface's own side behind q (lpv_walls_idle) two.
void weigh_pair(inout float low_weight, inout float high_weight, uint packed, float plane, float q, float facing) {
  if ((packed & WALL_COVER_BYTES) == 0u) return;
  vec4 located = lpv_walls_from_unorm(unpackUnorm4x8(packed));
  if (lpv_walls_idle(located, plane, q, facing)) return;
  low_weight *= lpv_walls_let_through(located, plane, q, plane - 0.5, facing);
  high_weight *= lpv_walls_let_through(located, plane, q, plane + 0.5, facing);
}

// The weights of the 8 cells around q (cell units), a point of a surface facing n, from `low`
// (their walls' words: load_walls), times what the located walls between q and each cell's
// centre let through, and none of a cell whose centre lies inside a thin solid
// (lpv_wall_inside); returns their new sum. The walls across axis k between q and a pair of
// cells along it lie about the plane low_k + 1, and the pair's cell on its low side holds them
// (the corner with bit k clear); an axis along which both of the pair are one cell (the grid's
// border) has none. Written out pair by pair, with constant indices: looped, the arrays went
// to memory and the forward pass took twice as long.
float weigh_by_walls(inout float weight[8], uvec4 words[8], ivec3 low, ivec3 last, vec3 q, vec3 n) {
  // A centre inside a thin solid holds no side's light (lpv_wall_inside).
  for (uint corner = 0u; corner < 8u; ++corner) weight[corner] *= 1.0 - unpackUnorm4x8(words[corner].w).x;
  if (low.x >= 0 && low.x < last.x) {
    float plane = float(low.x + 1);
    weigh_pair(weight[0], weight[1], words[0].x, plane, q.x, n.x);
    weigh_pair(weight[2], weight[3], words[2].x, plane, q.x, n.x);
    weigh_pair(weight[4], weight[5], words[4].x, plane, q.x, n.x);
    weigh_pair(weight[6], weight[7], words[6].x, plane, q.x, n.x);
  }
  if (low.y >= 0 && low.y < last.y) {
    float plane = float(low.y + 1);
    weigh_pair(weight[0], weight[2], words[0].y, plane, q.y, n.y);
    weigh_pair(weight[1], weight[3], words[1].y, plane, q.y, n.y);
    weigh_pair(weight[4], weight[6], words[4].y, plane, q.y, n.y);
    weigh_pair(weight[5], weight[7], words[5].y, plane, q.y, n.y);
  }
  if (low.z >= 0 && low.z < last.z) {
    float plane = float(low.z + 1);
    weigh_pair(weight[0], weight[4], words[0].z, plane, q.z, n.z);
    weigh_pair(weight[1], weight[5], words[1].z, plane, q.z, n.z);
    weigh_pair(weight[2], weight[6], words[2].z, plane, q.z, n.z);
    weigh_pair(weight[3], weight[7], words[3].z, plane, q.z, n.z);
  }
  return weight[0] + weight[1] + weight[2] + weight[3] + weight[4] + weight[5] + weight[6] + weight[7];
}

// A point's splat at q (cell units; lattice `low` + `f` on the cell centres), of a surface
// facing n, weighed by the walls
// between it and each of its 8 cells: the factors lpv_splat.glsl takes (8 unorm bytes), and
// the scale on its values that keeps their sum, all of it going to the cells it sees (faded
// where it sees less than LPV_WALL_LEAST_WEIGHT of them, as the lookup is).
uvec2 wall_splat_factors(uint c, vec3 q, vec3 n, ivec3 low, vec3 f, ivec3 last, out float scale) {
  uvec4 words[8];
  load_walls(c, low, last, words);
  float through[8];
  for (uint corner = 0u; corner < 8u; ++corner) through[corner] = 1.0;
  weigh_by_walls(through, words, low, last, q, n);
  uvec2 factors = uvec2(0u);
  float seen = 0.0;
  for (uint corner = 0u; corner < 8u; ++corner) {
    uint byte = uint(round(255.0 * through[corner]));
    factors[corner >> 2u] |= byte << (8u * (corner & 3u));
    vec3 w3 = mix(1.0 - f, f, vec3(ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u)));
    seen += w3.x * w3.y * w3.z * float(byte) / 255.0;
  }
  scale = 1.0 / max(seen, LPV_WALL_LEAST_WEIGHT);
  return factors;
}

#endif
