// Walls located within their cells (api::LineBlocking::located, docs/lpv.md "Shading", walls).
// Shared by C++ (tests) and GLSL (lpv_geometry_resolve.comp, lpv_walls.glsl) so both use one
// set of formulas; the conventions of lpv_sh.h, which must be included first (in the same
// precision).
//
// The geometry volume splats a blocker to the corner planes either side of it, with tent
// weights: a surface across axis k at P + t (0 <= t < 1, cell units, P a plane of corners)
// gives (1 - t) of its cover to plane P and t to plane P + 1. So the covers c of three
// consecutive planes, at one face's place across the axis, locate a lone surface within a cell
// of the middle one exactly: its cover is their sum and its offset from P their first moment
// over that,
//   T = c(P - 1) + c(P) + c(P + 1),   o = (c(P + 1) - c(P - 1)) / T   (-1 < o < 1).
// The surfaces facing +k and those facing -k are located apart (from the blockers' first
// moment m_k = sum p n_k and spread S_k = sum p |n_k|, they cover (S_k + m_k) / 2 and
// (S_k - m_k) / 2): a thin wall's two sides land together, but two surfaces facing each other
// across a gap, a room's wall and a block beside it, each stay where they are (located as one,
// they stood as a wall in the middle of the gap and hid its cells from both). Surfaces facing
// one way within a cell of each other merge at their cover-weighted mean place.
#if defined(__cplusplus) && defined(LPV_SH_DOUBLE)
#ifndef LPV_WALLS_DOUBLE_H
#define LPV_WALLS_DOUBLE_H
#define LPV_WALLS_BODY
#endif
#elif !defined(LPV_WALLS_H)
#define LPV_WALLS_H
#define LPV_WALLS_BODY
#endif

#ifdef LPV_WALLS_BODY
#undef LPV_WALLS_BODY

#ifdef __cplusplus
#ifdef LPV_SH_DOUBLE
namespace gpu_double {
using vec2 = glm::dvec2;
#else
namespace gpu {
using vec2 = glm::vec2;
#endif
using glm::clamp;
using glm::max;
using glm::min;
#define LPV_FUNC inline
#define LPV_CONST_F inline constexpr lpv_real
#else
#define lpv_real float
#define LPV_FUNC
#define LPV_CONST_F const float
#endif

// A plane's cover across its axis by the surfaces facing +k and by those facing -k, from the
// first moment's component m_k = sum p n_k of the blockers of a face in it and their spread
// S_k = sum p |n_k|.
LPV_FUNC vec2 lpv_wall_plane_covers(lpv_real moment, lpv_real spread) {
  return vec2(max(spread + moment, lpv_real(0)), max(spread - moment, lpv_real(0))) * lpv_real(0.5);
}

// The surfaces facing one way within a cell of plane P, from their covers of planes P - 1, P
// and P + 1 at one face's place: (their offset from P, in cells; their cover, 0 where there
// is none).
LPV_FUNC vec2 lpv_wall_locate(lpv_real below, lpv_real at, lpv_real above) {
  const lpv_real cover = below + at + above;
  if (!(cover > lpv_real(0))) return vec2(0.0f);
  return vec2(clamp((above - below) / cover, lpv_real(-1), lpv_real(1)), cover);
}

// The width (cells) over which a wall's stop ramps from none to all as it passes one end of a
// segment, so that nothing jumps as a wall, a surface or a VPL moves by a hair. Narrow: a cell
// holds the light of its centre's side, and a wall within half the ramp of the centre lets a
// share of it through to the other side, where it can be a hundredth of it (with 1/8, a hut's
// roof 0.03 cell under its top cells' centres let 0.27 of the sunlit light onto its ceiling).
// Four steps of the offsets' bytes (lpv_walls_to_unorm: 2/255 cell) wide, so that it still ramps.
LPV_CONST_F LPV_WALL_RAMP = 0.03125;

// A face's located walls: xy those facing +k, zw those facing -k (each lpv_wall_locate's).
// The texel holds them as bytes, an axis a word: the offsets over [-1, 1] and the covers over
// [0, LPV_WALL_COVER_KEPT] (from 1 on a cover stops all; more says only that there is more
// than one surface, as far as lpv_wall_share needs it). A point and the cell centres it
// exchanges light with lie within half a cell of the plane on either side, and a line from
// centre to centre crosses the plane's walls within half a cell of it: a wall further off (and
// half the ramp) matters to no one about this plane, and is kept as none (the plane next to it
// holds it), so that the lookup tests it once.
LPV_CONST_F LPV_WALL_COVER_KEPT = 2.0;
LPV_FUNC vec4 lpv_walls_to_unorm(vec4 walls) {
  const lpv_real reach = lpv_real(0.5) + lpv_real(0.5) * LPV_WALL_RAMP;
  if (!(abs(walls.x) < reach)) walls.y = lpv_real(0);
  if (!(abs(walls.z) < reach)) walls.w = lpv_real(0);
  const vec4 range = vec4(2.0f, LPV_WALL_COVER_KEPT, 2.0f, LPV_WALL_COVER_KEPT);
  return clamp((walls + vec4(1.0f, 0.0f, 1.0f, 0.0f)) / range, vec4(0.0f), vec4(1.0f));
}
LPV_FUNC vec4 lpv_walls_from_unorm(vec4 unorm) {
  return unorm * vec4(2.0f, LPV_WALL_COVER_KEPT, 2.0f, LPV_WALL_COVER_KEPT) - vec4(1.0f, 0.0f, 1.0f, 0.0f);
}

// The gather's lines run from centre to centre, so a line crossing plane P passes every wall
// within half a cell of it, and none further. A face's cover (lpv_gather_cover_texel) is
// scaled by this factor: the walls within half a cell of the plane (the located walls' covers,
// ramped over LPV_WALL_RAMP where they lie half-way to the next plane) over the cover the
// geometry volume splatted there (`at`, the sum of lpv_wall_plane_covers'). A wall then stops
// a line whole at the one plane it is nearest and at none else, where its splat's two shares
// stopped a line from the cell beside it in part (the wall in thin-wall-hut, 0.14 m from a
// plane of corners, let a sixth of the light through).
LPV_FUNC lpv_real lpv_wall_nearest(lpv_real offset) {
  return clamp((lpv_real(0.5) - abs(offset)) / LPV_WALL_RAMP + lpv_real(0.5), lpv_real(0), lpv_real(1));
}
LPV_FUNC lpv_real lpv_wall_share(vec4 walls, lpv_real at) {
  const lpv_real near = walls.y * lpv_wall_nearest(walls.x) + walls.w * lpv_wall_nearest(walls.z);
  return at > lpv_real(0) ? near / at : lpv_real(0);
}

// How much a cell's centre lies inside a thin solid: between a surface facing -k below it and
// one facing +k above it, which face apart as the two sides of a wall do (a room's walls, which
// face each other, hold a gap between them). A centre there holds no side's light, yet both
// sides' VPLs add to it and both sides' surfaces read it, each across its own side (which
// lpv_walls_let_through sets aside): a thin wall through a row of cells' centres lit the dark
// side along it (thin-wall-room, whose fitted grid puts its wall through them). So neither
// adds to it nor reads it (lpv_walls.glsl), the rest of the 8 cells taking its weight. From the
// walls located about the cell's two planes across k, `lower` half a cell below the centre and
// `upper` half a cell above; a surface counts in full from half a ramp past the centre. The
// lesser of the two sides' parts: a wall's two sides cover the same part of the face (their
// product counted a wall covering 0.99 of it as 0.98 inside).
LPV_FUNC lpv_real lpv_wall_on_side(vec2 wall, lpv_real side) {  // wall: its place from the centre (cells), its cover
  return min(wall.y, lpv_real(1)) * clamp(side * wall.x / LPV_WALL_RAMP + lpv_real(0.5), lpv_real(0), lpv_real(1));
}
LPV_FUNC lpv_real lpv_wall_inside(vec4 lower, vec4 upper) {
  const lpv_real below = max(lpv_wall_on_side(vec2(lower.z - lpv_real(0.5), lower.w), lpv_real(-1)),
                             lpv_wall_on_side(vec2(upper.z + lpv_real(0.5), upper.w), lpv_real(-1)));
  const lpv_real above = max(lpv_wall_on_side(vec2(lower.x - lpv_real(0.5), lower.y), lpv_real(1)),
                             lpv_wall_on_side(vec2(upper.x + lpv_real(0.5), upper.y), lpv_real(1)));
  return min(below, above);
}

// The least total weight the shading's lookup divides its cells' weights by where walls cut
// them: a point whose cells lie nearly all beyond walls gets their light faded, not magnified.
LPV_CONST_F LPV_WALL_LEAST_WEIGHT = 0.125;

// The fraction of the light between two points, `from` and `to` along the wall's axis (cell
// units), that a wall (lpv_wall_locate's) about `plane` stops: its cover (at most all) where it
// lies between them, ramped over LPV_WALL_RAMP at either end (so a wall through a cell's centre
// hides half of it).
LPV_FUNC lpv_real lpv_wall_stops(vec2 wall, lpv_real plane, lpv_real from, lpv_real to) {
  const lpv_real at = plane + wall.x;
  const lpv_real way = to >= from ? lpv_real(1) : lpv_real(-1);
  const lpv_real past_from = clamp((at - from) * way / LPV_WALL_RAMP + lpv_real(0.5), lpv_real(0), lpv_real(1));
  const lpv_real before_to = clamp((to - at) * way / LPV_WALL_RAMP + lpv_real(0.5), lpv_real(0), lpv_real(1));
  return min(wall.y, lpv_real(1)) * past_from * before_to;
}

// What a face's located walls, both ways, let through from a point of a surface whose normal
// has the component `facing` along their axis (0 for none). The surface's own side lies behind
// the point and faces the same way: the walls facing that way do not stop what the point sends
// or reads backwards, across its own plane (the shading weighs the cells there by the part in
// front of it: lpv_irradiance.glsl), in full where the surface faces along the axis (|facing|
// from LPV_WALL_FACING on), less and less as it turns to lie along it. The other side of a thin
// wall or a roof faces away, and stops what crosses it.
LPV_CONST_F LPV_WALL_FACING = 0.25;
LPV_FUNC lpv_real lpv_walls_let_through(vec4 walls, lpv_real plane, lpv_real from, lpv_real to, lpv_real facing) {
  const lpv_real backwards = (to - from) * facing < lpv_real(0) ? min(abs(facing) / LPV_WALL_FACING, lpv_real(1)) : lpv_real(0);
  const lpv_real own_plus = facing > lpv_real(0) ? backwards : lpv_real(0);
  const lpv_real own_minus = facing < lpv_real(0) ? backwards : lpv_real(0);
  return (lpv_real(1) - (lpv_real(1) - own_plus) * lpv_wall_stops(vec2(walls.x, walls.y), plane, from, to)) *
         (lpv_real(1) - (lpv_real(1) - own_minus) * lpv_wall_stops(vec2(walls.z, walls.w), plane, from, to));
}

// Whether a face's located walls stop nothing that lpv_walls_let_through weighs from the point
// `from` of a surface facing `facing`, whatever the other end: each is none, or the surface's
// own side (facing its way, |facing| from LPV_WALL_FACING on) at least half a ramp behind the
// point, which a segment backwards passes and a segment forwards never reaches. The lookup
// skips such a face (a surface's own faces, most of those it meets) untested.
LPV_FUNC bool lpv_walls_idle(vec4 walls, lpv_real plane, lpv_real from, lpv_real facing) {
  const lpv_real behind = lpv_real(0.5) * LPV_WALL_RAMP;
  const bool plus_idle = !(walls.y > lpv_real(0)) || (facing >= LPV_WALL_FACING && plane + walls.x - from <= -behind);
  const bool minus_idle = !(walls.w > lpv_real(0)) || (facing <= -LPV_WALL_FACING && plane + walls.z - from >= behind);
  return plus_idle && minus_idle;
}

#ifdef __cplusplus
}  // namespace gpu or gpu_double
#else
#undef lpv_real
#endif
#undef LPV_FUNC
#undef LPV_CONST_F

#endif  // LPV_WALLS_BODY
