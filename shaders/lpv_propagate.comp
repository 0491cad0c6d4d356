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
//
// Speed (lavapipe runs each invocation as one lane of an 8-wide SIMD program):
// - Each invocation walks a column of COLUMN_LENGTH cells along z, so the cells below
//   and above, and the face below, are carried from one step to the next instead of loaded
//   again, and the flux statistics are summed in the column and added once.
// - A subgroup's columns form a block (4x2 for 8 lanes, see column_of_lane), so a cell's
//   neighbours in x and y are mostly the cells other lanes hold at the same height, taken by
//   shuffles; only lanes on the block's edge load one neighbour per axis. A texel gather costs
//   lavapipe a loop over the lanes, a shuffle one permute.
// - The grid holds what a cell sends in sender form (lpv_sender_form): the 5 face values of
//   a neighbour are then one shared term plus or minus one coefficient each.
// - The far and side faces are summed apart and weighted by their solid angles once per cell.
// - Occlusion and bounces are specialization constants, not branches on the frame's flags:
//   lavapipe runs both sides of a branch under a lane mask, so a flag would make every face pay
//   for the blocking and reflection code even when off. The first iteration of an occluded
//   frame runs the occluded shader with no blockers (the same result up to float rounding:
//   flux * 1), so a frame compiles one variant, not two (lavapipe compiles at first use).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_shuffle : require
#include "shared/gpu_types.h"
#include "shared/lpv_propagate_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_PROPAGATE_GROUP, local_size_y = LPV_PROPAGATE_GROUP, local_size_z = 1) in;

layout(std140, set = 0, binding = PROPAGATE_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = PROPAGATE_GRIDS, rgba32f) uniform readonly imageBuffer grids;
layout(set = 0, binding = PROPAGATE_ACCUMULATED_R, rgba32f) uniform readonly imageBuffer accumulated_r;
layout(set = 0, binding = PROPAGATE_ACCUMULATED_G, rgba32f) uniform readonly imageBuffer accumulated_g;
layout(set = 0, binding = PROPAGATE_ACCUMULATED_B, rgba32f) uniform readonly imageBuffer accumulated_b;
layout(set = 0, binding = PROPAGATE_FACES, rgba32f) uniform readonly imageBuffer faces;  // lpv_face_texel
layout(set = 0, binding = PROPAGATE_FACE_ALBEDO, rgba32f) uniform readonly imageBuffer face_albedo;  // lpv_face_albedo_texel
layout(std430, set = 0, binding = PROPAGATE_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(std430, set = 0, binding = PROPAGATE_GRID_STORE) writeonly buffer GridStore { u64vec2 grid_store[]; };
layout(std430, set = 0, binding = PROPAGATE_ACCUMULATED_STORE_R) writeonly buffer AccumulatedR { u64vec2 accumulated_store_r[]; };
layout(std430, set = 0, binding = PROPAGATE_ACCUMULATED_STORE_G) writeonly buffer AccumulatedG { u64vec2 accumulated_store_g[]; };
layout(std430, set = 0, binding = PROPAGATE_ACCUMULATED_STORE_B) writeonly buffer AccumulatedB { u64vec2 accumulated_store_b[]; };
layout(push_constant) uniform Push { LpvPropagatePush push; };

// The faces' blocking potentials apply (when the frame has a geometry volume; from the second
// iteration on), and with them the light the blockers reflect (bounces: 2).
layout(constant_id = 0) const bool OCCLUDED = false;
layout(constant_id = 1) const bool BOUNCES = false;
layout(constant_id = 2) const uint COLUMN_LENGTH = LPV_PROPAGATE_COLUMN_CPU;

#include "shared/lpv_grid_flux.glsl"

// The gathered lobe weights w (axes' order: constant, x, y, z) as the SH the cell holds,
// (c0' w_0, -c1' w_y, c1' w_z, -c1' w_x) / pi with the cosine lobe's constants c0', c1' (one
// product, where a division by pi would stay a division on lavapipe). Its flux,
// 2 sqrt(pi) c0' w_0 / pi, is w_0 itself.
const vec2 LOBE_TO_SH = vec2(SH_COSINE_C0, SH_COSINE_C1) / LPV_PI;

// What a cell sends, per colour channel, in sender form; zero for a cell past the grid's edge.
struct Sender {
  vec4 e[3];
};

// The light a cell gathers, per channel, in the axes' order (constant, x, y, z): the fluxes
// through far faces and through side faces, each summed as flux * (1, n) over the faces'
// normals n and weighted by its solid angle at the end; and (bounces) the light the blockers
// reflect, already weighted.
struct Gathered {
  vec4 far[3];
  vec4 side[3];
  vec4 reflected[3];
};

Sender load_sender(ivec3 cell, uint which, uvec3 dims, float inside) {
  int texel = lpv_grid_texel(cell, 0, which, dims);
  return Sender(vec4[3](imageLoad(grids, texel) * inside, imageLoad(grids, texel + 1) * inside,
                        imageLoad(grids, texel + 2) * inside));
}

// The blocking SH of a face as h = (1 - its constant term, its linear terms / sqrt(5)) in the
// axes' order, so that with u = sqrt(5) <h.yzw, w> the fraction it lets through along w is
// lpv_transmitted's: clamp(h.x + u, 0, 1) for the one-sided lobe, clamp(1 - max(2 |u|, q), 0,
// 1) for the projected area, q the closed surfaces' part (transmitted() below); (1, 0, 0, 0),
// all through, when off.
vec4 face_transmission(vec4 blocking, float on) {
  vec4 g = blocking * on;
  return vec4(1.0 - SH_C0 * g.x, vec3(-g.w, -g.y, g.z) * (SH_C1 / LPV_SQRT5));
}

// The fraction let through for the faces' values u (see face_transmission) and closed
// blocking q: lpv.transfer.z selects the projected area (1) or the one-sided lobe (0), a
// uniform rather than a pipeline variant since it costs one abs and one mix.
vec4 transmitted(float h0, vec4 u, vec4 q) {
  return clamp(mix(h0 + u, 1.0 - max(2.0 * abs(u), q), lpv.transfer.z), 0.0, 1.0);
}

// One channel of a neighbour on axis a, travelling along sigma * a, in the axes' order
// permuted so that a comes first (e = (A, P_a, P_b, P_c), the accumulators likewise): the
// far face (value A + sqrt(5) sigma P_a) and the side faces +b, -b, +c, -c (values
// A + 2 sigma P_a +- P_b, +- P_c), each clamped at zero and times what its blockers let
// through (t_far, t_side).
void receive(inout vec4 far, inout vec4 side, vec4 e, float sigma, float t_far, vec4 t_side) {
  float f = max(e.x + (sigma * LPV_SQRT5) * e.y, 0.0) * t_far;
  float shared_term = e.x + (2.0 * sigma) * e.y;
  vec4 s = max(vec4(shared_term + e.z, shared_term - e.z, shared_term + e.w, shared_term - e.w), vec4(0.0)) * t_side;
  far.x += f;
  far.y += sigma * f;
  side.x += (s.x + s.y) + (s.z + s.w);
  side.z += s.x - s.y;
  side.w += s.z - s.w;
}

// The light the blockers of a face stop, reflected back (bounces: 2): diffuse around their
// mean normal, times their mean albedo. `unblocked` is the face's flux before blocking
// (solid angle included), w its direction.
// Projected blocking stops light from either side, so the normal turns to face the light.
void reflect_blocked(inout Gathered g, vec4 blocking, vec3 albedo, vec3 w, vec3 unblocked, float blocked) {
  vec3 mean_normal = vec3(-blocking.w, -blocking.y, blocking.z);
  vec3 n = dot(mean_normal, mean_normal) > 0.0 ? normalize(mean_normal) : -w;
  if (lpv.transfer.z > 0.0 && dot(n, w) > 0.0) n = -n;
  vec3 reflected = unblocked * blocked * albedo;
  for (int c = 0; c < 3; ++c) g.reflected[c] += reflected[c] * vec4(1.0, n);
}

// The 5 faces a neighbour's light enters through, for bounces: the same values as receive(),
// in world axes, with the light its blockers stop reflected. a = sigma times the face's axis,
// b and c the next two axes.
void reflect_neighbour(inout Gathered g, Sender n, vec4 blocking, vec3 spread, vec3 albedo, vec3 a, vec3 b, vec3 c) {
  vec3 dirs[5] = vec3[5](a, (2.0 * a + b) / LPV_SQRT5, (2.0 * a - b) / LPV_SQRT5, (2.0 * a + c) / LPV_SQRT5, (2.0 * a - c) / LPV_SQRT5);
  for (int f = 0; f < 5; ++f) {
    vec3 w = dirs[f];
    float omega = f == 0 ? LPV_FAR_FACE_SOLID_ANGLE : LPV_SIDE_FACE_SOLID_ANGLE;
    vec3 unblocked;
    for (int k = 0; k < 3; ++k) unblocked[k] = omega * max(n.e[k].x + LPV_SQRT5 * dot(n.e[k].yzw, w), 0.0);
    float blocked = 1.0 - lpv_transmitted(blocking, w, lpv_closed_blocking(spread, w), lpv.transfer.z);
    reflect_blocked(g, blocking, albedo, w, unblocked, blocked);
  }
}

// The face a neighbour's light enters through: its blockers' SH and the spread of their
// normals (zero when not occluded) and mean albedo (bounces only).
struct Face {
  vec4 blocking;
  vec3 spread;
  vec3 albedo;
};

// The face on the +axis side of `cell`.
Face load_face(ivec3 cell, int axis, uvec3 dims) {
  return Face(OCCLUDED ? imageLoad(faces, lpv_face_texel(cell, axis, dims)) : vec4(0.0),
              OCCLUDED ? imageLoad(faces, lpv_face_spread_texel(cell, axis, dims)).xyz : vec3(0.0),
              BOUNCES ? imageLoad(face_albedo, lpv_face_albedo_texel(cell, axis, dims)).rgb : vec3(0.0));
}

// Adds the light of neighbour n on axis `axis` (0, 1, 2 = x, y, z), travelling along sigma
// times it, entering through `face`.
void gather(inout Gathered g, Sender n, int axis, float sigma, Face face, float blocking_on) {
  vec4 h = face_transmission(face.blocking, blocking_on);
  // h and the sender forms in the axes' order permuted so that `axis` comes first.
  if (axis == 1) h = h.xzwy;
  if (axis == 2) h = h.xwyz;
  float t_far = 1.0;
  vec4 t_side = vec4(1.0);
  if (OCCLUDED) {
    // The spread in the same permuted axes; closed blocking is the same for +w and -w, and
    // for the side faces +b and -b (and +c and -c).
    vec3 spread = face.spread * blocking_on;
    if (axis == 1) spread = spread.yzx;
    if (axis == 2) spread = spread.zxy;
    float closed_far = lpv_closed_blocking(spread, vec3(1.0, 0.0, 0.0));
    float closed_b = lpv_closed_blocking(spread, vec3(2.0, 1.0, 0.0) * LPV_INV_SQRT5);
    float closed_c = lpv_closed_blocking(spread, vec3(2.0, 0.0, 1.0) * LPV_INV_SQRT5);
    t_far = transmitted(h.x, vec4((sigma * LPV_SQRT5) * h.y), vec4(closed_far)).x;
    float shared_term = (2.0 * sigma) * h.y;
    t_side = transmitted(h.x, vec4(shared_term + h.z, shared_term - h.z, shared_term + h.w, shared_term - h.w),
                         vec4(closed_b, closed_b, closed_c, closed_c));
  }
  for (int c = 0; c < 3; ++c) {
    if (axis == 0) receive(g.far[c], g.side[c], n.e[c], sigma, t_far, t_side);
    if (axis == 1) receive(g.far[c].xzwy, g.side[c].xzwy, n.e[c].xzwy, sigma, t_far, t_side);
    if (axis == 2) receive(g.far[c].xwyz, g.side[c].xwyz, n.e[c].xwyz, sigma, t_far, t_side);
  }
  if (BOUNCES) {
    vec3 a = vec3(0.0), b = vec3(0.0), c = vec3(0.0);
    a[axis] = sigma;
    b[(axis + 1) % 3] = 1.0;
    c[(axis + 2) % 3] = 1.0;
    reflect_neighbour(g, n, face.blocking * blocking_on, face.spread * blocking_on, face.albedo, a, b, c);
  }
}

// A neighbour inside the subgroup's block: what lane `lane` holds at the same height.
Sender shuffle_sender(Sender s, uint lane) {
  return Sender(vec4[3](subgroupShuffle(s.e[0], lane), subgroupShuffle(s.e[1], lane), subgroupShuffle(s.e[2], lane)));
}

// `loaded` where the lane loaded the neighbour itself, else `shuffled`; times `inside`.
Sender pick_sender(bool use_loaded, Sender loaded, Sender shuffled, float inside) {
  Sender s;
  for (int c = 0; c < 3; ++c) s.e[c] = (use_loaded ? loaded.e[c] : shuffled.e[c]) * inside;
  return s;
}

// The block of columns a subgroup takes: lanes in x-fastest order, `width` of them a row, at
// least 2 each way, so that a lane on the block's edge has its outside neighbour on one side
// only (4x2 for lavapipe's 8 lanes, 8x4 for 32). The device has at least 4 lanes a subgroup
// (Device checks); one larger than the work group holds it in its first lanes.
uvec2 block_size() {
  uint lanes = min(gl_SubgroupSize, LPV_PROPAGATE_GROUP * LPV_PROPAGATE_GROUP);
  uint width = min(LPV_PROPAGATE_GROUP, lanes / 2u);
  return uvec2(width, lanes / width);
}

// The column (x, y) of this invocation: its subgroup's block in the work group, its lane's
// place in the block. Built from the subgroup and lane ids rather than the local invocation
// index, so the blocks match the subgroups however the device forms them.
uvec2 column_of_lane(uvec2 block, uvec2 in_block) {
  uint blocks_per_row = LPV_PROPAGATE_GROUP / block.x;
  uvec2 origin = uvec2(gl_SubgroupID % blocks_per_row, gl_SubgroupID / blocks_per_row) * block;
  return gl_WorkGroupID.xy * LPV_PROPAGATE_GROUP + origin + in_block;
}

void main() {
  GpuLpvCascade grid = lpv.cascades[push.cascade];
  uvec3 udims = grid.dims.xyz;
  ivec3 dims = ivec3(udims);
  uvec2 block = block_size();
  uint lane = gl_SubgroupInvocationID;
  uvec2 in_block = uvec2(lane % block.x, lane / block.x);
  uvec2 column = column_of_lane(block, in_block);
  // Invocations past the grid (dims not a multiple of the group) work on its last column and
  // store nothing.
  bool in_grid = all(lessThan(column, udims.xy));
  ivec2 xy = min(ivec2(column), dims.xy - 1);
  int z_begin = int(gl_WorkGroupID.z * COLUMN_LENGTH);
  int z_end = min(z_begin + int(COLUMN_LENGTH), dims.z);
  uint source = (push.iteration + 1u) & 1u;  // iteration 1 reads grid 0 and writes grid 1
  uint target = push.iteration & 1u;
  float blocking_on = push.iteration >= 2u ? 1.0 : 0.0;
  // The lobe's directional terms times the transfer's factor (lpv_sh.h, LPV_SHARPENED_TRANSFER).
  vec4 lobe_to_sh = vec4(LOBE_TO_SH.x, vec3(LOBE_TO_SH.y * lpv.transfer.x));

  // A neighbour past the grid's edge sends nothing: it is read at the nearest cell and weighted
  // by zero, which lavapipe runs faster than a branch (both sides of a branch run under a mask).
  ivec2 lower_xy = max(xy - 1, ivec2(0));
  ivec2 upper_xy = min(xy + 1, dims.xy - 1);
  vec2 lower_inside = vec2(greaterThan(xy, ivec2(0)));
  vec2 upper_inside = vec2(lessThan(xy, dims.xy - 1));
  // The neighbour a lane on the block's edge loads itself, per axis: the lower one on the
  // block's lower edge, else the upper one (used on the upper edge only).
  bvec2 on_lower_edge = equal(in_block, uvec2(0u));
  bvec2 on_upper_edge = equal(in_block, block - 1u);
  ivec2 edge_x = ivec2(on_lower_edge.x ? lower_xy.x : upper_xy.x, xy.y);
  ivec2 edge_y = ivec2(xy.x, on_lower_edge.y ? lower_xy.y : upper_xy.y);
  // The lanes holding the neighbours inside the block (this lane's own on an edge, not read).
  uvec2 lower_lane = uvec2(on_lower_edge.x ? lane : lane - 1u, on_lower_edge.y ? lane : lane - block.x);
  uvec2 upper_lane = uvec2(on_upper_edge.x ? lane : lane + 1u, on_upper_edge.y ? lane : lane + block.x);

  Sender below = load_sender(ivec3(xy, max(z_begin - 1, 0)), source, udims, z_begin > 0 ? 1.0 : 0.0);
  Sender here = load_sender(ivec3(xy, z_begin), source, udims, 1.0);
  Face face_below = load_face(ivec3(xy, max(z_begin - 1, 0)), 2, udims);
  vec3 column_flux = vec3(0.0);
  for (int z = z_begin; z < z_end; ++z) {
    ivec3 cell = ivec3(xy, z);
    Sender above = load_sender(ivec3(xy, min(z + 1, dims.z - 1)), source, udims, z + 1 < dims.z ? 1.0 : 0.0);
    Face face_above = load_face(cell, 2, udims);

    Gathered g;
    for (int c = 0; c < 3; ++c) {
      g.far[c] = vec4(0.0);
      g.side[c] = vec4(0.0);
      g.reflected[c] = vec4(0.0);
    }
    ivec3 left = ivec3(lower_xy.x, xy.y, z), front = ivec3(xy.x, lower_xy.y, z);
    Sender beyond_x = load_sender(ivec3(edge_x, z), source, udims, 1.0);
    Sender beyond_y = load_sender(ivec3(edge_y, z), source, udims, 1.0);
    Sender next_x[2] = Sender[2](shuffle_sender(here, lower_lane.x), shuffle_sender(here, upper_lane.x));
    Sender next_y[2] = Sender[2](shuffle_sender(here, lower_lane.y), shuffle_sender(here, upper_lane.y));
    // Each neighbour's light enters through the face the two cells share: the +axis face of
    // the lower one.
    Sender left_sender = pick_sender(on_lower_edge.x, beyond_x, next_x[0], lower_inside.x);
    Sender right_sender = pick_sender(on_upper_edge.x, beyond_x, next_x[1], upper_inside.x);
    Sender front_sender = pick_sender(on_lower_edge.y, beyond_y, next_y[0], lower_inside.y);
    Sender back_sender = pick_sender(on_upper_edge.y, beyond_y, next_y[1], upper_inside.y);
    gather(g, left_sender, 0, 1.0, load_face(left, 0, udims), blocking_on);
    gather(g, right_sender, 0, -1.0, load_face(cell, 0, udims), blocking_on);
    gather(g, front_sender, 1, 1.0, load_face(front, 1, udims), blocking_on);
    gather(g, back_sender, 1, -1.0, load_face(cell, 1, udims), blocking_on);
    gather(g, below, 2, 1.0, face_below, blocking_on);
    gather(g, above, 2, -1.0, face_above, blocking_on);

    if (in_grid) {
      int texel = lpv_grid_texel(cell, 0, target, udims);
      int accumulated = lpv_accumulated_texel(cell, push.cascade, udims);
      vec4 sh[3];
      for (int c = 0; c < 3; ++c) {
        // Lobe weights (1, n) summed over the faces.
        vec4 w = LPV_FAR_FACE_SOLID_ANGLE * g.far[c] + LPV_SIDE_FACE_SOLID_ANGLE * g.side[c] + g.reflected[c];
        sh[c] = vec4(w.x, -w.z, w.w, -w.y) * lobe_to_sh;
        // What this cell sends in the next iteration, times the outgoing scale, so that its
        // face fluxes, negative ones dropped, add up to its flux (see lpv_outgoing_scale).
        vec4 sent = lpv_sender_form(sh[c]);
        grid_store[texel + c] = texel_bits(sent * lpv_sender_outgoing_scale(sent));
        column_flux[c] += w.x;
      }
      accumulated_store_r[accumulated] = texel_bits(imageLoad(accumulated_r, accumulated) + sh[0]);
      accumulated_store_g[accumulated] = texel_bits(imageLoad(accumulated_g, accumulated) + sh[1]);
      accumulated_store_b[accumulated] = texel_bits(imageLoad(accumulated_b, accumulated) + sh[2]);
    }
    below = here;
    here = above;
    face_below = face_above;
  }
  add_grid_flux(column_flux, push.stats_record, lpv.scales.x);
}
