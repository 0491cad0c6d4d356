#version 450
// Injection: the RSMs' texels (or blocks of vpl_downsample^2 texels, merged into one brighter
// VPL) are virtual point lights (shared/lpv_inject_vpl.glsl), as many as a cell needs: each
// invocation takes a tile of 4 x 4 of them and adds neighbours that lie close together as one
// VPL, so that a point light's texels next to it, hundreds to a cell, do not cost hundreds of
// splats (docs/lpv.md, "Injection").
//
// A VPL's SH are linear in its flux (lpv_inject_vpl.glsl: vpl_values), so VPLs merged at their
// flux-weighted centroid carry exactly their summed light; only where in the cell it is added
// moves, by less than the spacing LPV_VPLS_PER_CELL_SIDE allows. A 2 x 2 quad of the tile is
// merged where its points span at most that spacing once merged, the whole tile where all 16
// do; the rest are added one by one, as before. A view whose VPLs cannot lie that close (an
// orthographic one whose texels are wider: LpvInjectPass) skips the tiles, one VPL an
// invocation.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_vote : require
#include "shared/gpu_types.h"
#include "shared/lpv_inject_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_VPL_GROUP, local_size_y = LPV_VPL_GROUP) in;

layout(std140, set = 0, binding = INJECT_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = INJECT_RSM_POSITION, rgba32f) uniform readonly image2DArray rsm_position;
layout(set = 0, binding = INJECT_RSM_NORMAL, rgba32f) uniform readonly image2DArray rsm_normal;
layout(set = 0, binding = INJECT_RSM_FLUX, rgba32f) uniform readonly image2DArray rsm_flux;
layout(std430, set = 0, binding = INJECT_INJECTED) buffer Injected { int64_t injected[]; };  // 12 per cell: RGB x SH
layout(std430, set = 0, binding = INJECT_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(set = 0, binding = INJECT_WALLS, rgba32ui) uniform readonly uimageBuffer walls;
layout(push_constant) uniform Push { LpvInjectRsmPush push; };
// The geometry volume located its walls (lpv.line_blocking "located"): a VPL adds its light to
// the cells around it as far as the walls between it and their centres let it (lpv_walls.glsl).
layout(constant_id = 1) const bool LOCATED_WALLS = false;

#include "shared/lpv_grid_flux.glsl"
#include "shared/lpv_inject_vpl.glsl"
#include "shared/lpv_walls.glsl"

// The splat's factors for a VPL at `point` (cell units) facing `normal` (unit, or the mean of
// several) whose lattice is (low, f): the located walls', with its values scaled to keep its
// light; none without them.
uvec2 located_factors(vec3 point, vec3 normal, ivec3 low, vec3 f, inout float values[SPLAT_VALUES]) {
  if (!LOCATED_WALLS) return SPLAT_UNWEIGHED;
  float scale;
  uvec2 factors = wall_splat_factors(push.cascade, point, normal, low, f, vpl_last_cell(), scale);
  for (uint i = 0u; i < SPLAT_VALUES; ++i) values[i] *= scale;
  return factors;
}

// A VPL of the RSM, or several merged: where it is added (cell units), the flux that weighs
// its point, and what it adds.
struct Vpl {
  vec3 flux;      // all of it, for the statistics
  bool added;     // lit and inside the cascade
  vec3 point;     // vpl_grid_point
  vec3 normal;    // unit
  float weight;   // flux summed over the channels
  float values[SPLAT_VALUES];
};

// VPL `at` of the view: its block of vpl_downsample^2 texels, merged (flux adds up; position
// and normal are flux-weighted means).
Vpl read_vpl(uvec2 at) {
  uint block = lpv.sizes.y;
  uint vpls_per_side = push.vpls_per_side;
  vec3 flux = vec3(0.0);
  vec3 position = vec3(0.0);
  vec3 normal = vec3(0.0);
  for (uint y = 0u; at.x < vpls_per_side && at.y < vpls_per_side && y < block; ++y) {
    for (uint x = 0u; x < block; ++x) {
      ivec3 texel = ivec3(at * block + uvec2(x, y), push.layer);
      vec4 p = imageLoad(rsm_position, texel);
      if (p.w == 0.0) continue;
      vec3 f = imageLoad(rsm_flux, texel).rgb;
      float w = f.r + f.g + f.b;
      flux += f;
      position += w * p.xyz;
      normal += w * imageLoad(rsm_normal, texel).xyz;
    }
  }
  Vpl v;
  v.flux = flux;
  v.weight = flux.r + flux.g + flux.b;
  bool lit = v.weight > 0.0 && dot(normal, normal) > 0.0;
  vec3 n = lit ? normalize(normal) : vec3(0.0, 0.0, 1.0);
  v.point = lit ? vpl_grid_point(position / v.weight, n) : vec3(0.0);
  v.normal = n;
  vpl_values(n, flux, v.values);
  v.added = lit && lpv_inside_distance(lpv.cascades[push.cascade], v.point) >= 0.0;
  return v;
}

// VPLs being merged: their values and flux-weighted points summed, and the box of their points.
struct Merge {
  float values[SPLAT_VALUES];
  vec3 weighted_point;
  vec3 weighted_normal;
  float weight;
  vec3 lo;
  vec3 hi;
};

Merge empty_merge() {
  Merge m;
  for (uint i = 0u; i < SPLAT_VALUES; ++i) m.values[i] = 0.0;
  m.weighted_point = vec3(0.0);
  m.weighted_normal = vec3(0.0);
  m.weight = 0.0;
  m.lo = vec3(3.0e38);
  m.hi = vec3(-3.0e38);
  return m;
}

Merge merged(Merge a, Merge b) {
  for (uint i = 0u; i < SPLAT_VALUES; ++i) a.values[i] += b.values[i];
  a.weighted_point += b.weighted_point;
  a.weighted_normal += b.weighted_normal;
  a.weight += b.weight;
  a.lo = min(a.lo, b.lo);
  a.hi = max(a.hi, b.hi);
  return a;
}

Merge with_vpl(Merge m, Vpl v) {
  if (!v.added) return m;
  for (uint i = 0u; i < SPLAT_VALUES; ++i) m.values[i] += v.values[i];
  m.weighted_point += v.weight * v.point;
  m.weighted_normal += v.weight * v.normal;
  m.weight += v.weight;
  m.lo = min(m.lo, v.point);
  m.hi = max(m.hi, v.point);
  return m;
}

// Whether `side` x `side` VPLs whose points span the box [lo, hi] may be one: once merged they
// stand for a patch `side` spacings across, which must be at most a cell's side over
// LPV_VPLS_PER_CELL_SIDE. Their spacing is the box's span over side - 1, measured as the box's
// diagonal over sqrt 2 (a square patch's side, however it is turned).
bool mergeable(Merge m, float side) {
  float span = length(m.hi - m.lo) * 0.70710678;
  return m.weight > 0.0 && span * side * float(LPV_VPLS_PER_CELL_SIDE) <= side - 1.0;
}

// VPL k (0..3) of quad q (0..3) of the tile, x-fastest in both.
uvec2 tile_vpl(uvec2 tile, uint q, uint k) {
  return tile * LPV_INJECT_TILE + 2u * uvec2(q & 1u, q >> 1u) + uvec2(k & 1u, k >> 1u);
}

// VPLs that cannot be merged (push.merge 0): one an invocation.
void add_one_by_one(uvec2 at) {
  Vpl v = read_vpl(at);
  add_grid_flux(v.flux, push.stats_record, lpv.scales.x);
  ivec3 low;
  vec3 f;
  vpl_lattice(v.point, low, f);
  uvec2 factors = located_factors(v.point, v.normal, low, f, v.values);
  splat_subgroup(v.added, low, f, v.values, vpl_last_cell(), lpv.scales.x, factors);
}

void main() {
  uvec3 id = splat_group_point();
  if (push.merge == 0u) {
    add_one_by_one(id.xy);
    return;
  }
  uvec2 tile = id.xy;
  Merge quads[4];
  vec3 flux = vec3(0.0);
  for (uint q = 0u; q < 4u; ++q) {
    quads[q] = empty_merge();
    for (uint k = 0u; k < 4u; ++k) {
      Vpl v = read_vpl(tile_vpl(tile, q, k));
      flux += v.flux;
      quads[q] = with_vpl(quads[q], v);
    }
  }
  // The flux of all VPLs, for the statistics.
  add_grid_flux(flux, push.stats_record, lpv.scales.x);

  Merge whole = merged(merged(quads[0], quads[1]), merged(quads[2], quads[3]));
  bool whole_merged = mergeable(whole, 4.0);
  bool quad_merged[4];
  bool merges = whole_merged;
  for (uint q = 0u; q < 4u; ++q) {
    quad_merged[q] = !whole_merged && mergeable(quads[q], 2.0);
    merges = merges || quad_merged[q];
  }
  if (!subgroupAny(merges)) {
    // Nothing to merge (VPLs a quarter of a cell apart or more, as a sun's are): the run's 4x2
    // tiles' VPLs one by one, as compact 4x2 blocks of them at a time, so that a subgroup's
    // points share few cells (splat_subgroup).
    uvec2 run_first = (tile - splat_run_offset()) * LPV_INJECT_TILE;
    for (uint t = 0u; t < LPV_INJECT_TILE * LPV_INJECT_TILE; ++t) {
      Vpl v = read_vpl(run_first + uvec2((t % 4u) * 4u, (t / 4u) * 2u) + splat_run_offset());
      if (!subgroupAny(v.added)) continue;
      ivec3 low;
      vec3 f;
      vpl_lattice(v.point, low, f);
      uvec2 factors = located_factors(v.point, v.normal, low, f, v.values);
      splat_subgroup(v.added, low, f, v.values, vpl_last_cell(), lpv.scales.x, factors);
    }
    return;
  }
  for (uint q = 0u; q < 4u; ++q) {
    for (uint k = 0u; k < 4u; ++k) {
      // One of: the whole tile (q = k = 0), the quad (k = 0), or its VPL k alone.
      bool added;
      vec3 point;
      vec3 normal;
      float values[SPLAT_VALUES];
      if (whole_merged || quad_merged[q]) {
        Merge m = whole_merged ? whole : quads[q];
        added = k == 0u && (q == 0u || !whole_merged);
        point = m.weighted_point / max(m.weight, 1e-30);
        normal = m.weighted_normal / max(m.weight, 1e-30);
        values = m.values;
      } else {
        Vpl v = read_vpl(tile_vpl(tile, q, k));
        added = v.added;
        point = v.point;
        normal = v.normal;
        values = v.values;
      }
      if (!subgroupAny(added)) continue;
      ivec3 low;
      vec3 f;
      vpl_lattice(point, low, f);
      uvec2 factors = located_factors(point, normal, low, f, values);
      splat_subgroup(added, low, f, values, vpl_last_cell(), lpv.scales.x, factors);
    }
  }
}
