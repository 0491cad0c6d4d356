// Trilinear splatting of points into a lattice of 64-bit fixed-point sums (the injection of
// VPLs into cells, the geometry volume's surfels into cell corners). A point at lattice
// position low + f (0 <= f < 1) adds w(o) * values to the 8 lattice points low + o around it,
// w(o) the trilinear weight; lattice points past the border are clamped onto it, so nothing
// is lost. Fixed-point integer sums are associative: the result is the same in any order.
//
// Two ways to add:
// - splat_point: one invocation, one atomic add per lattice point and non-zero value.
// - splat_subgroup: the points of a subgroup, which nearly always lie close together
//   (neighbouring texels of a reflective shadow map or of the G-buffer), are summed first:
//   each invocation takes a lattice point of the box around the subgroup's points and
//   gathers every point's share of it in float, in the fixed order of the invocations (so the
//   sum is deterministic too), then adds it with one atomic per non-zero value. lavapipe
//   pays ~20 cycles for each atomic however uncontended: on the Cornell box at 32^3 the
//   injection took 7.5 ms this way, 12.6 with splat_point alone and 20 with an atomic for
//   every value, zeros included (measured once, when this was written). A subgroup whose
//   box has more than 4 lattice points per invocation falls back to splat_point. It needs
//   full subgroups (a shuffle from a lane with no invocation is undefined): the callers'
//   8x8 work groups give them on lavapipe and on GPUs with subgroups of 8 to 64 (lavapipe's
//   4x4x4 groups number their subgroups past gl_NumSubgroups, so do not count on those),
//   and the flux conservation tests would see a lost or invented share.
//
// Each point may weigh its 8 lattice points by factors of its own (`factors`, 8 unorm bytes,
// lattice point low + o at byte o.x + 2 o.y + 4 o.z): the injection's located walls
// (lpv_walls.glsl), its values already scaled so that their sum is kept. SPLAT_UNWEIGHED
// (all 1) keeps the trilinear weights alone, at their cost.
//
// lpv.injection "nearest" (TRILINEAR_INJECTION false) puts each point at its nearest lattice
// point only (the paper's way: cheaper, but a point moved by a hair can jump a whole cell).
//
// The includer defines before the include:
//   SPLAT_VALUES              the number of values per lattice point,
//   SPLAT_ACTIVE_VALUES       (optional) how many of them, from the first, a pipeline splats
//                             (a specialization constant; the rest are left alone),
//   SPLAT_SUMS                its int64_t buffer array of the sums,
//   uint splat_index(ivec3)   the index in SPLAT_SUMS of a lattice point's first value.
#ifndef LPV_SPLAT_GLSL
#define LPV_SPLAT_GLSL

#ifndef SPLAT_ACTIVE_VALUES
#define SPLAT_ACTIVE_VALUES SPLAT_VALUES
#endif

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_shuffle : require

// A specialization constant, so each pipeline runs one of the two ways.
layout(constant_id = 0) const bool TRILINEAR_INJECTION = true;

// The splat of a point at lattice position t: trilinear, the lattice point below and the
// fraction past it; nearest, the nearest lattice point with no fraction.
void splat_lattice(vec3 t, out ivec3 low, out vec3 f) {
  low = ivec3(floor(TRILINEAR_INJECTION ? t : t + 0.5));
  f = TRILINEAR_INJECTION ? t - vec3(low) : vec3(0.0);
}

// The weight the point (low, f) gives lattice point `cell`, with the clamping to [0, last]:
// separable, the product over the axes of the weights of the (one or two) steps o landing on it.
float splat_weight(ivec3 cell, ivec3 low, vec3 f, ivec3 last) {
  vec3 at_low = mix(vec3(0.0), 1.0 - f, equal(clamp(low, ivec3(0), last), cell));
  vec3 at_high = mix(vec3(0.0), f, equal(clamp(low + 1, ivec3(0), last), cell));
  vec3 w = at_low + at_high;
  return w.x * w.y * w.z;
}

const uvec2 SPLAT_UNWEIGHED = uvec2(0xffffffffu);

// The factor a point's `factors` give its lattice point low + o, o = the corner's bits.
float splat_factor(uvec2 factors, uint corner) {
  return float((factors[corner >> 2u] >> (8u * (corner & 3u))) & 0xffu) / 255.0;
}

// splat_weight with the point's own factors: the sum over its corners that land on `cell`.
float splat_weight(ivec3 cell, ivec3 low, vec3 f, ivec3 last, uvec2 factors) {
  if (factors == SPLAT_UNWEIGHED) return splat_weight(cell, low, f, last);
  if (all(greaterThanEqual(low, ivec3(0))) && all(lessThan(low, last))) {  // no corner clamped: one lands on `cell`
    ivec3 o = cell - low;
    if (any(lessThan(o, ivec3(0))) || any(greaterThan(o, ivec3(1)))) return 0.0;
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    return w3.x * w3.y * w3.z * splat_factor(factors, uint(o.x + 2 * o.y + 4 * o.z));
  }
  float w = 0.0;
  for (uint corner = 0u; corner < 8u; ++corner) {
    ivec3 o = ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
    if (clamp(low + o, ivec3(0), last) != cell) continue;
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    w += w3.x * w3.y * w3.z * splat_factor(factors, corner);
  }
  return w;
}

void splat_point(ivec3 low, vec3 f, float values[SPLAT_VALUES], ivec3 last, float units, uvec2 factors) {
  for (uint corner = 0u; corner < 8u; ++corner) {
    ivec3 o = ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    float w = w3.x * w3.y * w3.z * splat_factor(factors, corner);
    if (w == 0.0) continue;
    uint base = splat_index(clamp(low + o, ivec3(0), last));
    for (uint i = 0u; i < SPLAT_ACTIVE_VALUES; ++i) {
      if (values[i] != 0.0) atomicAdd(SPLAT_SUMS[base + i], to_fixed(values[i] * w, units));
    }
  }
}

// This invocation's place in its run's 4x2 block (splat_group_point).
uvec2 splat_run_offset() {
  uint lane = gl_LocalInvocationIndex % 8u;
  return uvec2(lane % 4u, lane / 4u);
}

// The point (RSM texel, VPL or camera sample) of this invocation, for the callers' 8x8 work
// groups: each run of 8 invocations (a lavapipe subgroup) takes a 4x2 block instead of a row
// of 8. The block spans about half as many cells across, so its subgroup's box has fewer
// lattice points and fewer atomics (inject 4.5 -> 4.1 ms, geometry volume 4.1 -> 3.7 at 32^3,
// one-off alternated runs, commit bcd1d7a). Which invocation takes which point changes
// nothing else.
uvec3 splat_group_point() {
  uint run = gl_LocalInvocationIndex / 8u;
  uvec2 in_group = uvec2((run % 2u) * 4u, (run / 2u) * 2u) + splat_run_offset();
  return uvec3(gl_WorkGroupID.xy * gl_WorkGroupSize.xy + in_group, gl_WorkGroupID.z);
}

// Lattice points per invocation a subgroup may gather before it falls back to splat_point.
const uint SPLAT_LATTICE_PER_INVOCATION = 4u;

// Every invocation of the subgroup must call this, in uniform control flow; `valid` says
// whether this one has a point.
void splat_subgroup(bool valid, ivec3 low, vec3 f, float values[SPLAT_VALUES], ivec3 last, float units,
                    uvec2 factors) {
  const int NONE = 0x7fffffff;
  if (!valid) {  // adds nothing: zero values, at a finite point (no NaN into the sums)
    low = ivec3(0);
    f = vec3(0.0);
    factors = SPLAT_UNWEIGHED;
    for (uint i = 0u; i < SPLAT_ACTIVE_VALUES; ++i) values[i] = 0.0;
  }
  ivec3 lo = subgroupMin(valid ? clamp(low, ivec3(0), last) : ivec3(NONE));
  ivec3 hi = subgroupMax(valid ? clamp(low + ivec3(TRILINEAR_INJECTION), ivec3(0), last) : ivec3(-NONE));
  if (lo.x > hi.x) return;  // no point in the subgroup
  ivec3 box = hi - lo + 1;
  uint lattice = uint(box.x * box.y * box.z);
  if (lattice > SPLAT_LATTICE_PER_INVOCATION * gl_SubgroupSize) {
    if (valid) splat_point(low, f, values, last, units, factors);
    return;
  }
  for (uint first = 0u; first < lattice; first += gl_SubgroupSize) {
    uint index = first + gl_SubgroupInvocationID;
    ivec3 cell = lo + ivec3(index % uint(box.x), (index / uint(box.x)) % uint(box.y), index / uint(box.x * box.y));
    float sums[SPLAT_VALUES];
    for (uint i = 0u; i < SPLAT_ACTIVE_VALUES; ++i) sums[i] = 0.0;
    for (uint p = 0u; p < gl_SubgroupSize; ++p) {
      float w = splat_weight(cell, subgroupShuffle(low, p), subgroupShuffle(f, p), last, subgroupShuffle(factors, p));
      for (uint i = 0u; i < SPLAT_ACTIVE_VALUES; ++i) sums[i] += w * subgroupShuffle(values[i], p);
    }
    if (index >= lattice) continue;
    uint base = splat_index(cell);
    for (uint i = 0u; i < SPLAT_ACTIVE_VALUES; ++i) {
      if (sums[i] != 0.0) atomicAdd(SPLAT_SUMS[base + i], to_fixed(sums[i], units));
    }
  }
}

#endif
