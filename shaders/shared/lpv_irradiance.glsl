// Indirect irradiance from the LPV's accumulated grids, shared by the deferred shading
// (shade.comp) and the forward pass (forward.frag) so both light alike. The includer declares
// before the include:
//   CASCADES (uint)   the cascades of indirect light (a specialization constant, so the
//                     cascade loop has a constant length and is unrolled),
//   lpv (GpuLpv), accumulated_r, accumulated_g, accumulated_b (imageBuffer, rgba32f;
//                     lpv_accumulated_texel's layout), walls (uimageBuffer, rgba32ui: the
//                     walls located about the cells' faces, LpvVolumes::walls), and includes
//                     lpv_sh.h and lpv_grid.glsl;
// and leaves specialization constants 6 to 8 to this file (UNIFORM_BRANCHES, IRRADIANCE_CUBE,
// LOCATED_WALLS).
#ifndef LPV_IRRADIANCE_GLSL
#define LPV_IRRADIANCE_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_KHR_shader_subgroup_ballot : require

// The device runs only the taken side of a branch every lane of a subgroup agrees on
// (DeviceInfo::uniform_branches): the lookup below shares its cells between lanes only then.
layout(constant_id = 6) const bool UNIFORM_BRANCHES = true;
// The accumulated light is the gather's irradiance cube (lpv_gather.h): two texels a cell and
// channel, the irradiance onto surfaces facing +x, -x, +y, -y, then +z, -z; else one, its SH.
layout(constant_id = 7) const bool IRRADIANCE_CUBE = false;
// The geometry volume located its walls (lpv.line_blocking "located", lpv_walls.h): a cell lights
// a surface as far as the walls between its centre and the lookup's point let it.
layout(constant_id = 8) const bool LOCATED_WALLS = false;

#include "lpv_walls.glsl"

// Which of the 8 cells around a point corner k is: one step up along x, y, z for bits 0, 1, 2.
bvec3 corner_step(uint k) { return bvec3(k & 1u, k & 2u, k & 4u); }

// The part of a cell in front of the plane through `surface` (cell units) facing n: for a
// normal along an axis, exactly the fraction of the cell on the plane's front side. Light in a
// cell behind a surface cannot reach its front: the cell beyond a thin wall, or the surface's
// own cell, whose light its own blockers have partly stopped (docs/lpv.md, "Shading").
float in_front(ivec3 cell, vec3 surface, vec3 n) {
  return clamp(dot(vec3(cell) + 0.5 - surface, n) + 0.5, 0.0, 1.0);
}

// Corner k of set A or of set B, whichever this lane filters. Every lane shuffles both, and
// only then chooses: a shuffle reads the value of a lane that runs it, and a lane that took
// the other side of a branch would not. `two_sets` is the same in every lane: where all filter
// set A (most subgroups: a cell spans many pixels), set B is neither loaded nor shuffled.
vec4 shared_corner(vec4 of_a, vec4 of_b, uint k, bool in_a, bool two_sets) {
  vec4 a = subgroupShuffle(of_a, k);
  if (!two_sets) return a;
  vec4 b = subgroupShuffle(of_b, k);
  return in_a ? a : b;
}
vec3 shared_corner(vec3 of_a, vec3 of_b, uint k, bool in_a, bool two_sets) {
  vec3 a = subgroupShuffle(of_a, k);
  if (!two_sets) return a;
  vec3 b = subgroupShuffle(of_b, k);
  return in_a ? a : b;
}
uvec4 shared_corner(uvec4 of_a, uvec4 of_b, uint k, bool in_a, bool two_sets) {
  uvec4 a = subgroupShuffle(of_a, k);
  if (!two_sets) return a;
  uvec4 b = subgroupShuffle(of_b, k);
  return in_a ? a : b;
}


// The intensity of one cell, per channel, against a cosine lobe: each channel's SH made
// nowhere negative first (sh_nonnegative_irradiance), so that a cell next to a lit surface does
// not shade it with negative light that cancels what other cells send.
vec3 cell_irradiance(vec4 red, vec4 green, vec4 blue, vec4 lobe) {
  return vec3(dot(sh_nonnegative_irradiance(red), lobe), dot(sh_nonnegative_irradiance(green), lobe),
              dot(sh_nonnegative_irradiance(blue), lobe));
}

// The light of one cell's irradiance cube (lpv_gather.h) along the three axes a surface with
// normal n faces, per channel: the two texels a channel holds, +x, -x, +y, -y then +z, -z.
struct CubeAxes {
  vec3 x, y, z;
};
CubeAxes facing_axes(int texel, vec3 n) {
  vec4 r_xy = imageLoad(accumulated_r, 2 * texel), g_xy = imageLoad(accumulated_g, 2 * texel),
       b_xy = imageLoad(accumulated_b, 2 * texel);
  vec4 r_z = imageLoad(accumulated_r, 2 * texel + 1), g_z = imageLoad(accumulated_g, 2 * texel + 1),
       b_z = imageLoad(accumulated_b, 2 * texel + 1);
  CubeAxes axes;
  axes.x = n.x >= 0.0 ? vec3(r_xy.x, g_xy.x, b_xy.x) : vec3(r_xy.y, g_xy.y, b_xy.y);
  axes.y = n.y >= 0.0 ? vec3(r_xy.z, g_xy.z, b_xy.z) : vec3(r_xy.w, g_xy.w, b_xy.w);
  axes.z = n.z >= 0.0 ? vec3(r_z.x, g_z.x, b_z.x) : vec3(r_z.y, g_z.y, b_z.y);
  return axes;
}
// The cube's irradiance onto the surface: its axes blended by the squares of the normal's
// components, n2 (exact for a normal along an axis; the weights sum to 1).
vec3 cube_irradiance(CubeAxes axes, vec3 n2) { return n2.x * axes.x + n2.y * axes.y + n2.z * axes.z; }

// The mean radiance (W/(m^2 sr)) a cell of cascade c holds: the intensity per unit face area of
// its SH's constant term, or its irradiance cube's mean over pi (an isotropic radiance L gives
// pi L on every axis).
vec3 cell_mean_radiance(uint c, ivec3 cell) {
  GpuLpvCascade g = lpv.cascades[c];
  int texel = lpv_accumulated_texel(cell, c, g.dims.xyz);
  vec3 mean;
  if (IRRADIANCE_CUBE) {
    vec4 r_xy = imageLoad(accumulated_r, 2 * texel), g_xy = imageLoad(accumulated_g, 2 * texel),
         b_xy = imageLoad(accumulated_b, 2 * texel);
    vec4 r_z = imageLoad(accumulated_r, 2 * texel + 1), g_z = imageLoad(accumulated_g, 2 * texel + 1),
         b_z = imageLoad(accumulated_b, 2 * texel + 1);
    vec4 ones = vec4(1.0);
    mean = vec3(dot(r_xy, ones) + r_z.x + r_z.y, dot(g_xy, ones) + g_z.x + g_z.y, dot(b_xy, ones) + b_z.x + b_z.y) /
           (6.0 * LPV_PI);
  } else {
    mean = SH_C0 * vec3(imageLoad(accumulated_r, texel).x, imageLoad(accumulated_g, texel).x,
                        imageLoad(accumulated_b, texel).x);
  }
  return max(mean, vec3(0.0)) / (g.origin.w * g.origin.w);
}

// Irradiance (W/m^2) from the accumulated intensity of cascade c around q (cell units, half a
// cell in front of the surface) onto a surface with normal n: trilinear between cell centres,
// each cell's weight times the part of it in front of the surface (in_front) and the weights
// renormalised (they sum to at least 3/4: the cells half a cell or more in front count fully),
// then E = <I, cosine lobe of -n> / s^2 (a cell's intensity per unit face area is the radiance
// that crosses it). q is clamped to the centres of the border cells, so the filter never mixes
// in the next cascade, stacked above this one in the same buffers.
//
// Neighbouring pixels mostly filter the same 8 cells (a cell spans many pixels), or one of two
// sets of 8 where the subgroup's pixels straddle a cell's boundary. When every lane of the
// subgroup filters set A or set B (the lowest corners of the subgroup's smallest and largest
// texel index) and all lanes run, lane k loads corner k mod 8 of both sets (of set A alone
// where every lane filters it) and every lane takes its 8 corners from them by shuffles: 3 to
// 6 texel loads a lane instead of 24 for SH, 6 to 12 instead of 48 for a cube. lavapipe runs
// a texel load as a call over the lanes, a shuffle by a constant lane as one permute, and
// branches for real on a condition every lane shares (Mesa 25). A device that runs both sides
// of such a branch (lavapipe before Mesa 25: the forward pass 2.3 times slower on 22.3) would
// pay for both paths, so there each lane loads its own (UNIFORM_BRANCHES). The values and the
// sums are the same either way, so the picture is too, bit for bit.
vec3 cascade_irradiance(uint c, vec3 q, vec3 n) {
  GpuLpvCascade g = lpv.cascades[c];
  ivec3 last = ivec3(g.dims.xyz) - 1;
  vec3 t = clamp(q - 0.5, vec3(0.0), vec3(last));  // in units of cell centres
  ivec3 low = ivec3(t);
  vec3 f = t - vec3(low);
  ivec3 high = min(low + 1, last);
  vec4 lobe = sh_cosine_lobe(-n);
  vec3 n2 = n * n;
  // Each corner's weight: trilinear, times the part of its cell in front of the surface (and
  // what the located walls let through, once its cells are known: weigh_by_walls).
  vec3 surface = q - 0.5 * n;
  float weight[8];
  float total = 0.0;
  for (uint corner = 0u; corner < 8u; ++corner) {
    vec3 w3 = mix(1.0 - f, f, corner_step(corner));
    ivec3 cell = mix(low, high, corner_step(corner));
    weight[corner] = (w3.x * w3.y * w3.z) * in_front(cell, surface, n);
    total += weight[corner];
  }
  vec3 e = vec3(0.0);
  int key = lpv_accumulated_texel(low, c, g.dims.xyz);
  int key_a = key, key_b = key;
  bool shared_cells = false;
  if (UNIFORM_BRANCHES) {
    // Each condition of the && is the same in every lane, so the lanes that run the first
    // all run the subgroup operations after it.
    key_a = subgroupMin(key);
    key_b = subgroupMax(key);
    uvec3 octant = uvec3(greaterThanEqual(n, vec3(0.0)));
    shared_cells = gl_SubgroupSize >= 8u && subgroupAdd(1u) == gl_SubgroupSize && subgroupAll(key == key_a || key == key_b) &&
                   (!IRRADIANCE_CUBE || subgroupAll(octant == subgroupBroadcastFirst(octant)));
  }
  if (shared_cells) {
    bool two_sets = key_a != key_b;
    bool in_a = key == key_a;
    ivec3 low_a = subgroupShuffle(low, subgroupMin(key == key_a ? gl_SubgroupInvocationID : gl_SubgroupSize));
    ivec3 low_b = subgroupShuffle(low, subgroupMin(key == key_b ? gl_SubgroupInvocationID : gl_SubgroupSize));
    bvec3 step = corner_step(gl_SubgroupInvocationID & 7u);
    int mine_a = lpv_accumulated_texel(mix(low_a, min(low_a + 1, last), step), c, g.dims.xyz);
    int mine_b = lpv_accumulated_texel(mix(low_b, min(low_b + 1, last), step), c, g.dims.xyz);
    if (LOCATED_WALLS) {  // the cells' walls shared as their light is
      uvec4 walls_a = imageLoad(walls, mine_a), walls_b = walls_a;
      if (two_sets) walls_b = imageLoad(walls, mine_b);
      uvec4 words[8];
      for (uint corner = 0u; corner < 8u; ++corner) words[corner] = shared_corner(walls_a, walls_b, corner, in_a, two_sets);
      total = weigh_by_walls(weight, words, low, last, q, n);
    }
    if (IRRADIANCE_CUBE) {
      // Every lane's normal faces the same octant (the condition of shared_cells), so the lane
      // that loads a corner picks the axes each lane would. Where the lanes share one normal too
      // (a flat surface), it blends them for all: 3 values a corner shuffled instead of 9.
      CubeAxes a = facing_axes(mine_a, n), b = a;
      if (two_sets) b = facing_axes(mine_b, n);
      if (subgroupAll(n == subgroupBroadcastFirst(n))) {
        vec3 blended_a = cube_irradiance(a, n2), blended_b = blended_a;
        if (two_sets) blended_b = cube_irradiance(b, n2);
        for (uint corner = 0u; corner < 8u; ++corner)
          e += weight[corner] * shared_corner(blended_a, blended_b, corner, in_a, two_sets);
      } else {
        for (uint corner = 0u; corner < 8u; ++corner) {
          CubeAxes axes;
          axes.x = shared_corner(a.x, b.x, corner, in_a, two_sets);
          axes.y = shared_corner(a.y, b.y, corner, in_a, two_sets);
          axes.z = shared_corner(a.z, b.z, corner, in_a, two_sets);
          e += weight[corner] * cube_irradiance(axes, n2);
        }
      }
    } else {
      vec4 red_a = imageLoad(accumulated_r, mine_a), green_a = imageLoad(accumulated_g, mine_a),
           blue_a = imageLoad(accumulated_b, mine_a);
      vec4 red_b = red_a, green_b = green_a, blue_b = blue_a;
      if (two_sets) {
        red_b = imageLoad(accumulated_r, mine_b);
        green_b = imageLoad(accumulated_g, mine_b);
        blue_b = imageLoad(accumulated_b, mine_b);
      }
      for (uint corner = 0u; corner < 8u; ++corner)
        e += weight[corner] * cell_irradiance(shared_corner(red_a, red_b, corner, in_a, two_sets),
                                              shared_corner(green_a, green_b, corner, in_a, two_sets),
                                              shared_corner(blue_a, blue_b, corner, in_a, two_sets), lobe);
    }
  } else {
    if (LOCATED_WALLS) {
      uvec4 words[8];
      load_walls(c, low, last, words);
      total = weigh_by_walls(weight, words, low, last, q, n);
    }
    for (uint corner = 0u; corner < 8u; ++corner) {
      int cell = lpv_accumulated_texel(mix(low, high, corner_step(corner)), c, g.dims.xyz);
      if (IRRADIANCE_CUBE) {
        e += weight[corner] * cube_irradiance(facing_axes(cell, n), n2);
      } else {
        e += weight[corner] * cell_irradiance(imageLoad(accumulated_r, cell), imageLoad(accumulated_g, cell),
                                              imageLoad(accumulated_b, cell), lobe);
      }
    }
  }
  return max(e, vec3(0.0)) / (max(total, LOCATED_WALLS ? LPV_WALL_LEAST_WEIGHT : 1e-6) * g.origin.w * g.origin.w);
}

// Indirect irradiance at p: the finest cascade that holds p, handing over to the next coarser
// one across its border band. Sampled half a cell along the normal, against self-lighting.
// The loop has no exit on `remaining` reaching 0 (the coarser cascades then add 0): with a
// data-dependent exit it is not unrolled, and the single-cascade default shaded 30% slower.
vec3 indirect_irradiance(vec3 p, vec3 n) {
  vec3 e = vec3(0.0);
  float remaining = 1.0;
  for (uint c = 0u; c < CASCADES; ++c) {
    GpuLpvCascade g = lpv.cascades[c];
    vec3 q = lpv_grid_position(g, p + 0.5 * g.origin.w * n);
    float inside = lpv_inside_distance(g, q);
    if (inside < 0.0) continue;
    float w = c + 1u == CASCADES ? 1.0 : clamp(inside / float(LPV_BLEND_CELLS), 0.0, 1.0);
    if (w == 0.0) continue;
    e += remaining * w * cascade_irradiance(c, q, n);
    remaining *= 1.0 - w;
  }
  return e;
}

#endif
