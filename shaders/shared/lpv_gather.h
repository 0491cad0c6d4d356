// The gather transfer (api::Transfer::gather, docs/lpv.md "The gather"): every cell of a
// cascade gathers the light of every injected cell directly, along the straight line between
// them, instead of receiving it one propagation step at a time. Shared by C++ (the CPU
// reference of tests/lpv) and GLSL (lpv_gather.comp) so both use one set of formulas; the
// conventions of lpv_sh.h, which must be included first (in the same precision).
//
// A cell's result is an irradiance cube: for each of the 6 axis directions a, the irradiance
// onto a surface facing a (times s^2, the grid's units: lpv_sh.h), which the shading blends by
// the squares of the normal's components (lpv_irradiance.glsl). Two-band SH cannot hold light
// that arrives from one side: they give a surface facing it 3/4 of its irradiance and a
// surface it grazes 1/4, so a ceiling lit from a patch of floor got 0.7 of its light and a
// floor lit by far-off parts of itself got some. The cube is exact for surfaces along the axes.
#if defined(__cplusplus) && defined(LPV_SH_DOUBLE)
#ifndef LPV_GATHER_DOUBLE_H
#define LPV_GATHER_DOUBLE_H
#define LPV_GATHER_BODY
#endif
#elif !defined(LPV_GATHER_H)
#define LPV_GATHER_H
#define LPV_GATHER_BODY
#endif

#ifdef LPV_GATHER_BODY
#undef LPV_GATHER_BODY

#ifdef __cplusplus
#ifdef LPV_SH_DOUBLE
namespace gpu_double {
#else
namespace gpu {
#endif
using glm::clamp;
using glm::floor;
using glm::ivec3;
using glm::min;
#define LPV_FUNC inline
#define LPV_CONST_F inline constexpr lpv_real
#define LPV_CONST_I inline constexpr int
#else
#define lpv_real float
#define LPV_FUNC
#define LPV_CONST_F const float
#define LPV_CONST_I const int
#endif

// A source cell stands for about a cell face of lit surface: its light at distance r falls
// off as 1 / (r^2 + 1/pi) (cell units), the irradiance on the axis of a disc of that area,
// which stays finite next to it where a point's 1/r^2 does not.
LPV_CONST_F LPV_GATHER_SOURCE_AREA_TERM = 0.3183098862;  // 1 / pi

// The 6 axis directions of the irradiance cube, in its order: +x, -x, +y, -y, +z, -z.
LPV_FUNC vec3 lpv_cube_axis(int a) {
  vec3 axis = vec3(0.0f);
  axis[a / 2] = a % 2 == 0 ? lpv_real(1) : lpv_real(-1);
  return axis;
}

// What an injected cell emits, from its injected SH summed over the channels: the mean normal
// of its VPLs (xyz, unit or zero) and how coherent they are (w, |mean normal| in [0, 1]: 1 for
// one surface, 0 for opposite faces that cancel). Injection adds a VPL of flux phi facing n as
// phi / (4 pi) (1 + 2 f <n, w>) (f = `injection`, lpv.transfer.y), so the band-1 vector over
// the constant term is 2 f times the flux-weighted mean normal.
LPV_FUNC vec4 lpv_gather_emitter(vec4 summed_sh, lpv_real injection) {
  const vec3 band1 = SH_C1 * vec3(-summed_sh.w, -summed_sh.y, summed_sh.z);
  const lpv_real constant = SH_C0 * summed_sh.x;
  if (!(constant > lpv_real(0))) return vec4(0.0f);
  const vec3 m = band1 / (lpv_real(2) * injection * constant);
  const lpv_real coherence = min(sqrt(dot(m, m)), lpv_real(1));
  return coherence > lpv_real(0) ? vec4(normalize(m), coherence) : vec4(0.0f);
}

// The emitter's intensity towards unit w per unit of flux / pi: a cosine lobe about its normal
// for its coherent part, isotropic (1/4: the same flux) for the rest. Nothing leaves a surface
// backwards or along itself, which the two-band SH of a lobe (1/4 + 1/2 <n, w>) would send.
LPV_FUNC lpv_real lpv_gather_lobe(vec4 emitter, vec3 w) {
  const vec3 n = vec3(emitter.x, emitter.y, emitter.z);
  return (lpv_real(1) - emitter.w) * lpv_real(0.25) + emitter.w * max(dot(n, w), lpv_real(0));
}

// The irradiance onto a surface facing cube axis a (times s^2), per unit of flux / pi of the
// source, from a source at offset d (cell units) from the gathering cell's centre, unoccluded.
// The surface is taken half a cell behind the cell's centre along a: the shading reads each
// surface from the cells 0 to 1 cell in front of it (lpv_irradiance.glsl), so half a cell
// is where the surfaces a cell lights lie on average. Measured at the centre, a floor missed
// the light of the wall beside it from below the centre's height, the nearest and brightest.
LPV_FUNC lpv_real lpv_gather_axis(vec4 emitter, vec3 d, int a) {
  const vec3 axis = lpv_cube_axis(a);
  const vec3 to_surface = d - lpv_real(0.5) * axis;
  const lpv_real r2 = dot(to_surface, to_surface);
  const vec3 w = to_surface / sqrt(r2);
  return lpv_gather_lobe(emitter, w) * max(-dot(w, axis), lpv_real(0)) / (r2 + LPV_GATHER_SOURCE_AREA_TERM);
}

// A face's blockers lie within a cell of it along their normal: the geometry volume splats
// each surface to the corners of the cell around it, and a face takes the mean of its corners.
LPV_CONST_F LPV_GATHER_BLOCKER_REACH = 1.0;  // cells

// The blockers' first moment m = sum p n, from their SH; whether their plane, through the face's
// centre along m, separates the line's ends by more than LPV_GATHER_BLOCKER_REACH.
LPV_FUNC vec3 lpv_gather_first_moment(vec4 b) { return vec3(-b.w, -b.y, b.z) / SH_COSINE_C1; }  // sum p n (b = sum p cosine lobe(n))
LPV_FUNC bool lpv_gather_separates(vec3 m, vec3 to_source, vec3 to_cell) {
  const lpv_real length_m = sqrt(dot(m, m));
  if (!(length_m > lpv_real(0))) return false;
  const lpv_real source_side = dot(to_source, m) / length_m;
  const lpv_real cell_side = dot(to_cell, m) / length_m;
  const lpv_real reach = LPV_GATHER_BLOCKER_REACH;
  return (source_side < -reach && cell_side > reach) || (source_side > reach && cell_side < -reach);
}

// The fraction of light along unit w, on the line from a source to the gathering cell, that
// crosses a face whose blockers have the SH b (their potentials times their cosine lobes) and
// the spread of their normals (lpv_sh.h, "Blocking"); `to_source` and `to_cell` go from the
// face's centre to the line's two ends (cell units). The open part (the first moment m,
// stopping |<m, w>|: the blockers' area across the light) stops the light only where the
// blockers' plane, through the face's centre along m, separates the two ends by more than
// LPV_GATHER_BLOCKER_REACH: only then does the line certainly pass through the surface. A
// surface a line starts or ends at, or runs beside within a cell, does not stop it: a source's
// own wall passes the light leaving it, a ceiling the light arriving at it, a floor the light
// grazing it, which propagation's faces stop wherever they hold the surface. The closed part
// (both sides of a thin wall, a solid's faces, which cancel in m) stops light wherever it
// crosses the face. It is the lesser of two estimates: the spread's projected area beyond the
// first moment's (which completes a solid's, its open faces counted by m), and the spread of
// the normals that cancel along each axis, |n_k| summed less |m_k| (nothing for a crease
// where a floor meets a wall, whose two normals cancel nowhere; the first took such a crease
// for a closed surface and stopped the light between the floor and the wall).
LPV_FUNC lpv_real lpv_gather_transmitted(vec4 b, vec3 spread, vec3 w, vec3 to_source, vec3 to_cell) {
  const vec3 m = lpv_gather_first_moment(b);
  const lpv_real u = dot(m, w);
  const lpv_real closed = min(max(lpv_closed_blocking(spread, w) - abs(u), lpv_real(0)),
                             lpv_closed_blocking(max(spread - abs(m), vec3(lpv_real(0))), w));
  const lpv_real open_part = lpv_gather_separates(m, to_source, to_cell) ? abs(u) : lpv_real(0);
  return lpv_real(1) - clamp(open_part + closed, lpv_real(0), lpv_real(1));
}

// Blocking along a line (api::LineBlocking, docs/lpv.md "The gather", 8). The geometry
// volume splats a blocker to the corners of the cell around it and a face takes the mean of its
// corners, so a wall lies in the faces within a cell of it: across its own axis in the two
// planes of corners either side of it, in shares that sum to the wall (halves for a wall in the
// middle of a cell), and in the faces of the other axes between those planes. Multiplied face
// by face ("multiplied"), the shares of a wall that stops a line whole let (1 - 1/2)^2 = 1/4
// through at mid-cell, and more to an oblique line, whose faces across the other axes hold
// only the wall's projection.
//
// Paired ("paired"), each face across axis k stops what the blockers facing along k cover of it
// (lpv_gather_face_cover), whatever the line's angle: a line crossing a plane meets the part of
// it a wall covers, at any angle, and a wall across k meets the line only in faces across k.
// The faces across k are met in pairs: a face's cover is added to the last one's across the same
// axis before it stops the light, (1 - (c_last + c)) / (1 - c_last) of it, so that the two shares
// of one wall stop what the wall covers, (1 - c_1) (1 - (c_1 + c_2)) / (1 - c_1) = 1 - c_1 - c_2,
// and walls further apart still stop the light each in turn. Blockers spread evenly through
// space (cover c on every face) let (1 - 2c) / (1 - c) of the light through a face, not 1 - c.
//
// A line's state: the fraction it lets through so far (x) and the covers of the last face it
// crossed across each axis (yzw, for "paired"). A walk continues from the state it is given.
LPV_FUNC vec4 lpv_gather_line_begin() { return vec4(1.0f, 0.0f, 0.0f, 0.0f); }
LPV_FUNC vec4 lpv_gather_line_blocked() { return vec4(0.0f); }
LPV_FUNC bool lpv_gather_line_open(vec4 line) { return line.x > lpv_real(0); }
LPV_FUNC lpv_real lpv_gather_line_through(vec4 line) { return max(line.x, lpv_real(0)); }
LPV_FUNC vec4 lpv_gather_line_multiply(vec4 line, lpv_real face_through) {
  line.x *= face_through;
  return line;
}
LPV_FUNC vec4 lpv_gather_line_pair(vec4 line, int axis, lpv_real cover) {
  const lpv_real last = line[1 + axis];
  const lpv_real before = lpv_real(1) - min(last, lpv_real(1));
  line.x = before > lpv_real(0) ? line.x * (lpv_real(1) - min(last + cover, lpv_real(1))) / before : lpv_real(0);
  line[1 + axis] = cover;
  return line;
}

// The part of a face across `axis` that its blockers facing along the axis cover, for the line
// from `to_source` to `to_cell` (from the face's centre, cell units; lpv_gather_transmitted's
// rules): the one-sided part, |m_k| of the first moment m = sum p n, where the blockers' plane
// (through the face's centre along m) separates the line's ends by more than
// LPV_GATHER_BLOCKER_REACH; the closed part, (sum p |n_k| - |m_k|) / 2 (both sides of a thin
// wall, a solid's opposite faces), wherever the line crosses. Blockers facing the other axes
// stop the line in the faces across theirs.
//
// What a face holds for it, computed once a frame by the geometry volume's resolve
// (lpv_geometry_resolve.comp, the face cover texels): m, and the closed part across `axis`.
LPV_FUNC vec4 lpv_gather_cover_texel(vec4 b, vec3 spread, int axis) {
  const vec3 m = lpv_gather_first_moment(b);
  return vec4(m.x, m.y, m.z, lpv_real(0.5) * max(spread[axis] - abs(m[axis]), lpv_real(0)));
}
LPV_FUNC lpv_real lpv_gather_face_cover(vec4 cover_texel, int axis, vec3 w, vec3 to_source, vec3 to_cell) {
  const vec3 m = vec3(cover_texel.x, cover_texel.y, cover_texel.z);
  const lpv_real across = dot(abs(m), abs(w));
  const lpv_real one_sided = across > lpv_real(0) ? abs(m[axis]) * abs(dot(m, w)) / across : lpv_real(0);
  return (lpv_gather_separates(m, to_source, to_cell) ? one_sided : lpv_real(0)) + cover_texel.w;
}

// The line from a source cell's centre to the gathering cell's, d = (their offset), crosses
// |d_k| faces across axis k, at the parameters t = n / (2 |d_k|) for n = 1, 3, 5, ... (0 at the
// source, 1 at the gathering cell). Which comes first is decided in integers, so that a line
// through an edge or a corner crosses its faces in the same order in float and in double:
// x before y before z on a tie. `next` holds each axis's next n, `span` the |d_k|; an axis
// that is never crossed (span 0) never comes first.
LPV_FUNC bool lpv_gather_crosses_first(int next_a, int span_a, int next_b, int span_b) {
  if (span_b == 0) return true;
  if (span_a == 0) return false;
  return next_a * span_b <= next_b * span_a;
}
LPV_FUNC int lpv_gather_next_axis(ivec3 next, ivec3 span) {
  if (lpv_gather_crosses_first(next.x, span.x, next.y, span.y) && lpv_gather_crosses_first(next.x, span.x, next.z, span.z))
    return 0;
  return lpv_gather_crosses_first(next.y, span.y, next.z, span.z) ? 1 : 2;
}

// Shared far lines (lpv.far_lines "per_block"): the line from a far record's start to a cell
// is walked to the cell of the cell's 2 x 2 x 2 block (aligned, cut by the grid's end) nearest
// the start, once for the block, then per cell over the faces between there and the cell, each
// met as the line from the start to the cell meets it. The 8 cells' lines to a far source (at
// least two cells from the block) part only in their last faces.
LPV_FUNC ivec3 lpv_gather_shared_end(ivec3 start, ivec3 cell, ivec3 dims) {
  const ivec3 lo = (cell >> 1) << 1;
  return clamp(start, lo, min(lo + ivec3(1), dims - ivec3(1)));
}

// A cell's own injected light onto a surface facing cube axis a: its SH against the cosine
// lobe, made nowhere negative first, as the propagated grids are read (lpv_irradiance.glsl).
// Its VPLs lie within the cell, where no direction to them is defined.
LPV_FUNC lpv_real lpv_gather_own_cell(vec4 sh, int a) {
  return max(dot(sh_nonnegative_irradiance(sh), sh_cosine_lobe(-lpv_cube_axis(a))), lpv_real(0));
}

// The sources, as a pyramid (docs/lpv.md, "The gather"). A cell gathers the lit cells near it
// one by one and those further off in blocks, each block's light summed and placed at its
// centroid: level 0 holds the cells, level L blocks of 2^L cells a side (the last ones of an
// axis cut short by the grid's end). Which level a source is gathered at is the fast multipole
// method's rule, with blocks one block apart counted as far: a cell c gathers the level-L
// blocks whose parent (at level L + 1) lies next to c's (or is c's), except, above level 0,
// the blocks next to c's own, which it gathered at finer levels. Every source is gathered
// exactly once, at the coarsest level at which it is more than a block from c; so a block is
// always at least its own size away, a cell's nearest 2 to 3 cells a side come one by one,
// and each cell gathers a few hundred records whatever the grid, where it gathered every lit
// cell of it before.
//
// A record is three texels: the sum of its cells' injected SH over the channels (whose band 1
// gives the emitter: lpv_gather_emitter), each channel's flux / pi, and the flux-weighted
// centroid of its cells' centres (cell units of level 0), where its light comes from.
LPV_CONST_I LPV_GATHER_RECORD_TEXELS = 3;

// Blocks per axis at a level.
LPV_FUNC ivec3 lpv_gather_level_dims(ivec3 dims, int level) { return (dims + ivec3((1 << level) - 1)) >> level; }
LPV_FUNC int lpv_gather_level_blocks(ivec3 dims, int level) {
  const ivec3 d = lpv_gather_level_dims(dims, level);
  return d.x * d.y * d.z;
}
// The first record of a level: the levels are stored one after another, blocks x-fastest.
LPV_FUNC int lpv_gather_level_first(ivec3 dims, int level) {
  int first = 0;
  for (int k = 0; k < level; ++k) first += lpv_gather_level_blocks(dims, k);
  return first;
}
// Levels down to a single block, and the records of all of them.
LPV_FUNC int lpv_gather_levels(ivec3 dims) {
  int levels = 1;
  while (lpv_gather_level_blocks(dims, levels - 1) > 1) ++levels;
  return levels;
}
LPV_FUNC int lpv_gather_records(ivec3 dims) { return lpv_gather_level_first(dims, lpv_gather_levels(dims)); }

// The blocks of a level that cell c gathers from lie in [lo, hi] (clipped to the grid), less
// those next to c's own above level 0 (lpv_gather_gathered_finer). Where the range covers the
// whole level, c gathers everything left there and `last` ends its climb.
struct LpvGatherWindow {
  ivec3 lo;
  ivec3 hi;
  bool last;
};
LPV_FUNC LpvGatherWindow lpv_gather_window(ivec3 cell, int level, ivec3 dims) {
  const ivec3 level_dims = lpv_gather_level_dims(dims, level);
  const ivec3 parent = cell >> (level + 1);
  LpvGatherWindow window;
  window.lo = max(parent * 2 - ivec3(2), ivec3(0));
  window.hi = min(parent * 2 + ivec3(3), level_dims - ivec3(1));
  window.last = window.lo.x == 0 && window.lo.y == 0 && window.lo.z == 0 && window.hi.x == level_dims.x - 1 &&
                window.hi.y == level_dims.y - 1 && window.hi.z == level_dims.z - 1;
  return window;
}
LPV_FUNC bool lpv_gather_gathered_finer(ivec3 block, ivec3 cell, int level) {
  const ivec3 apart = abs(block - (cell >> level));
  return level > 0 && apart.x <= 1 && apart.y <= 1 && apart.z <= 1;
}

// Where a cell's light left its surfaces: the injection moved each VPL `offset` cells along its
// normal before adding it to the cells around (lpv_inject_vpl.glsl), so the flux-weighted mean
// of its VPLs lies that far from the surface along their mean normal (the emitter's normal
// times its coherence). The cell's centre stands for the VPLs' mean.
LPV_FUNC vec3 lpv_gather_surface(vec3 cell_centre, vec4 emitter, lpv_real offset) {
  return cell_centre - offset * emitter.w * vec3(emitter.x, emitter.y, emitter.z);
}

// The cell a record's line of sight starts from: the one its light was added around (its
// centre moved back along the mean normal: lpv_gather_surface), clamped to the grid. For a cell
// that is the cell itself; for a block, the one holding most of its light. Rounded a hair
// below the half so that a centre halfway between two cells (two equal ones) rounds the same
// way in float and in double.
LPV_CONST_F LPV_GATHER_ROUNDING = 0.4921875;  // 1/2 - 1/128
LPV_FUNC ivec3 lpv_gather_line_start(vec3 centre, vec4 emitter, lpv_real offset, ivec3 dims) {
  const vec3 added = centre + offset * emitter.w * vec3(emitter.x, emitter.y, emitter.z);
  return clamp(ivec3(floor(added + vec3(LPV_GATHER_ROUNDING))), ivec3(0), dims - ivec3(1));
}

// The bounces after the last one gathered ("bounces": "all", docs/lpv.md "Bounces"): light
// that keeps bouncing in a room settles into one shape, each bounce r times the one before, r
// the room's share of the light it reflects back. The last gathered bounce's light, which its
// surfaces reflect as `reflected` of the `gathered` flux it came from, stands for that shape,
// and the bounces after it add r + r^2 + ... = r / (1 - r) of it, r = reflected / gathered.
// r is at most LPV_BOUNCE_TAIL_MAX_RATIO: in a closed room of albedo 1 every bounce carries all
// the light, and the sum has no end (the tail is then 9 times the last bounce).
LPV_CONST_F LPV_BOUNCE_TAIL_MAX_RATIO = 0.9f;
LPV_FUNC lpv_real lpv_bounce_tail_factor(lpv_real gathered, lpv_real reflected) {
  if (!(gathered > lpv_real(0))) return lpv_real(0);
  const lpv_real r = clamp(reflected / gathered, lpv_real(0), LPV_BOUNCE_TAIL_MAX_RATIO);
  return r / (lpv_real(1) - r);
}

#ifdef __cplusplus
}  // namespace gpu or gpu_double
#else
#undef lpv_real
#endif
#undef LPV_FUNC
#undef LPV_CONST_F
#undef LPV_CONST_I

#endif  // LPV_GATHER_BODY
