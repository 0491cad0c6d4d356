// Two-band spherical harmonics and the propagation geometry of Light Propagation Volumes,
// shared by C++ (tests, CPU references) and GLSL (the LPV passes) so both use one set of
// formulas. Conventions: DESIGN.md section 2 and the LPV annotations in shared/seeds/.
//
// An SH vector is a vec4 per colour channel in the basis order (Y00, Y1-1, Y10, Y11):
//   Y(d) = (c0, -c1 d.y, c1 d.z, -c1 d.x),  c0 = 1 / (2 sqrt(pi)),  c1 = sqrt(3) / (2 sqrt(pi)).
// The grid stores radiant intensity I(w) in W/sr; its flux is the integral over the sphere,
// which only the DC term carries: flux = 4 pi c0 s0 = 2 sqrt(pi) s0.
// C++ includes it once per scalar type: in float as namespace gpu (what the shaders compute)
// and, with LPV_SH_DOUBLE defined, in double as namespace gpu_double (the CPU reference's
// double-precision runs). Scalars are lpv_real: float in GLSL.
#if defined(__cplusplus) && defined(LPV_SH_DOUBLE)
#ifndef LPV_SH_DOUBLE_H
#define LPV_SH_DOUBLE_H
#define LPV_SH_BODY
#endif
#elif !defined(LPV_SH_H)
#define LPV_SH_H
#define LPV_SH_BODY
#endif

#ifdef LPV_SH_BODY
#undef LPV_SH_BODY

#ifdef __cplusplus
#include <glm/glm.hpp>
#ifdef LPV_SH_DOUBLE
namespace gpu_double {
using lpv_real = double;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
#else
namespace gpu {
using lpv_real = float;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
#endif
using glm::abs;
using glm::clamp;
using glm::dot;
using std::sqrt;
using glm::max;
using glm::normalize;
#define LPV_FUNC inline
#define LPV_CONST_F inline constexpr lpv_real
#else
#define lpv_real float
#define LPV_FUNC
#define LPV_CONST_F const float
#endif

LPV_CONST_F SH_C0 = 0.2820947918;  // 1 / (2 sqrt(pi))
LPV_CONST_F SH_C1 = 0.4886025119;  // sqrt(3) / (2 sqrt(pi))

// Clamped cosine lobe max(0, <n, w>) projected on the basis: (sqrt(pi)/2, sqrt(pi/3) n)
// with the basis's signs. (The annotations' last line says s1 for the x term; it is s3.)
LPV_CONST_F SH_COSINE_C0 = 0.8862269255;  // sqrt(pi) / 2
LPV_CONST_F SH_COSINE_C1 = 1.0233267079;  // sqrt(pi / 3)

// Solid angles of the faces of a neighbouring cell, seen from the source cell's centre:
// the far face 4 asin(1/10), each of the four side faces 2 atan(3 / sqrt(11)) - pi/3.
// far + 4 side = 2 pi / 3, so six neighbours cover the sphere exactly. (A widely copied
// side value, 0.4234413544, has two digits swapped.)
LPV_CONST_F LPV_FAR_FACE_SOLID_ANGLE = 0.4006696846;
LPV_CONST_F LPV_SIDE_FACE_SOLID_ANGLE = 0.4234313544;

// The sharpened transfer (api::Transfer::sharpened, docs/lpv.md "The transfer"): the factor on
// the directional (band-1) terms of the lobe a cell gathers in one propagation step. Each face's
// flux re-emitted as a cosine lobe spreads light sideways every step (a beam along an axis
// sends more than half its flux to the four lateral neighbours), so light above a lit floor
// turns downward and lights the floor it left. The light above a uniformly lit plane is a
// uniform hemisphere, I(w) = A (1 + 3/2 <n, w>) in 2-band SH; exact transport carries it
// unchanged. Gathered from 6 neighbours sending it, the cosine lobes' sum has directional terms
// k = 0.24533 of its flux, which re-emitted as a lobe is a ratio of 2k, not 3/2: this factor,
// 3/2 / (2k), makes that field a fixed point of one step, so a lit plane's light keeps its
// shape instead of spilling back onto the plane. It changes no flux (the constant term is
// untouched; lpv_outgoing_scale drops the negative faces it makes). tests/lpv/
// test_lpv_propagation.cpp propagates that field on the CPU reference and checks it keeps its
// shape with this factor (and prints 2k without it).
LPV_CONST_F LPV_SHARPENED_TRANSFER = 3.0570784452;
// With it, each VPL is injected as that same hemisphere, directional terms 3/2 of its constant
// term instead of the cosine lobe's 2 (a factor 3/4 on band 1; the flux is the same): a VPL
// stands for a patch of lit surface, and the light above a lit surface is the hemisphere the
// transfer keeps. It lights its own surface with exactly zero, where a cosine lobe gives
// -1/3 of its constant term, which the shading's clamp at zero then subtracted from the light
// other surfaces send there (the Cornell box's floor by a wall got none).
LPV_CONST_F LPV_SHARPENED_INJECTION = 0.75;

LPV_CONST_F LPV_PI = 3.14159265358979;
LPV_CONST_F LPV_SQRT_PI = 1.7724538509;
LPV_CONST_F LPV_SQRT5 = 2.2360679775;
LPV_CONST_F LPV_INV_SQRT5 = 0.4472135955;  // 1 / sqrt(5)

// The basis functions in direction d (unit).
LPV_FUNC vec4 sh_basis(vec3 d) { return vec4(SH_C0, -SH_C1 * d.y, SH_C1 * d.z, -SH_C1 * d.x); }

// The clamped cosine lobe around unit n.
LPV_FUNC vec4 sh_cosine_lobe(vec3 n) {
  return vec4(SH_COSINE_C0, -SH_COSINE_C1 * n.y, SH_COSINE_C1 * n.z, -SH_COSINE_C1 * n.x);
}

// The function an SH vector represents, in direction d.
LPV_FUNC lpv_real sh_evaluate(vec4 sh, vec3 d) { return dot(sh, sh_basis(d)); }

// Blocking (api::Blocking, docs/lpv.md "Blocking"). A face's blocking SH b is the sum of its
// blockers' potentials p (area / face area) times their cosine lobes (lpv_geometry_inject.comp),
// so b holds sum p in its constant term and the first moment m = sum p n in band 1, and its
// value towards -w is sum p (1/4 + 1/2 <n, -w>): the one-sided lobe the paper evaluates
// (sh_lobe, `projected` = 0). That lobe stops a quarter of the light grazing a surface, which
// over the steps along a floor or a wall removes most of the light travelling beside it, and
// only 3/4 of the light meeting it head-on. An opaque surfel stops the fraction p |<n, w>| of
// light along w, its area projected across w, from either side (projected, `projected` = 1):
// |<m, w>| = 2 |band-1 part|, exact for one plane. Blockers facing opposite ways on one face
// cancel in m: both sides of a wall thinner than a cell, which the scene's surfaces always
// give (and the views' surfels where both sides are seen). The spread of their normals does
// not cancel (lpv_closed_blocking): the projected blocking stops the larger of the two, `closed`.
// Returns the fraction let through, in [0, 1].
LPV_FUNC lpv_real lpv_transmitted(vec4 b, vec3 w, lpv_real closed, lpv_real projected) {
  const lpv_real one_sided = sh_evaluate(b, -w);
  const lpv_real directional = one_sided - SH_C0 * b.x;
  const lpv_real blocked = one_sided + projected * (max(lpv_real(2) * abs(directional), closed) - one_sided);
  return lpv_real(1) - clamp(blocked, lpv_real(0), lpv_real(1));
}

// The projected area across w of blockers that may be closed surfaces, from the sums of
// their normals' absolute components, spread = sum p |n| (per axis). Each blocker's |<n, w>|
// is at most sum_k |n_k| |w_k|, with equality when w lies along an axis (every far face) or
// n does, or both lie in one quadrant: so <spread, |w|> is exact for any surface in the far
// faces' directions and for surfaces along the axes in every direction, and too large by up
// to 3 times for a slanted one in some side directions. It counts the two sides of a thin
// wall twice, as a closed surface's sides add up (a ray crosses it twice): half of it is
// the closed surfaces' projected area, and for one open plane half of its own (the first
// moment gives that one in full: lpv_transmitted takes the larger).
LPV_FUNC lpv_real lpv_closed_blocking(vec3 spread, vec3 w) { return lpv_real(0.5) * dot(spread, abs(w)); }

// An SH vector whose irradiance is nowhere negative (docs/lpv.md, "Shading"). The irradiance of
// a 2-band SH onto a surface facing n, <s, cosine lobe(-n)>, is least against the band-1 vector,
// where it is c0' s0 - c1' |band 1|: a cell whose light is more directional than a hemisphere
// (the sharpened lobes next to a lit surface are) shades the surface it leaves with negative
// light, which cancels what other surfaces send there before the clamp at zero. Band 1 is
// scaled down to the largest length that keeps every direction's irradiance >= 0 (the flux,
// the constant term, is kept); nothing else changes.
LPV_FUNC vec4 sh_nonnegative_irradiance(vec4 s) {
  const lpv_real limit = SH_COSINE_C0 / SH_COSINE_C1 * max(s.x, lpv_real(0));
  const vec3 band1 = vec3(s.y, s.z, s.w);
  const lpv_real length1 = sqrt(dot(band1, band1));
  if (length1 <= limit) return s;
  const vec3 kept = band1 * (limit / length1);
  return vec4(max(s.x, lpv_real(0)), kept.x, kept.y, kept.z);
}

// The flux of an intensity distribution: its integral over the sphere.
LPV_FUNC lpv_real sh_flux(vec4 sh) { return 2.0f * LPV_SQRT_PI * sh.x; }

// A diffuse emitter of flux phi facing n: I(w) = phi / pi * max(0, <n, w>), whose integral
// over the sphere is phi (the annotations' correction 4.1 of the paper's missing 1/pi).
LPV_FUNC vec4 sh_diffuse_emitter(vec3 n, lpv_real phi) { return sh_cosine_lobe(n) * (phi / LPV_PI); }

// Unit direction from a source cell's centre to the centre of a face of the neighbour that
// lies along unit axis `ahead`: `side` = 0 for the far face, else the unit axis (orthogonal
// to `ahead`) the side face faces. The far face centre is 1.5 cells ahead; a side face
// centre is 1 cell ahead and half a cell to the side.
LPV_FUNC vec3 lpv_face_direction(vec3 ahead, vec3 side) { return normalize(ahead + lpv_real(0.5) * side); }

// What a cell sends, in the form propagation reads it: I(w) = A + sqrt(5) <P, w>, stored as
// (A, P) with A = c0 s0 and P = c1 (-s3, -s1, s2) / sqrt(5) (axes x, y, z). The value on a
// neighbour's far face, A + sqrt(5) P_a, and on its side faces, A + 2 P_a +- P_b, then take
// one shared term and an addition each.
LPV_FUNC vec4 lpv_sender_form(vec4 sh) {
  return vec4(SH_C0 * sh.x, -SH_C1 * LPV_INV_SQRT5 * sh.w, -SH_C1 * LPV_INV_SQRT5 * sh.y, SH_C1 * LPV_INV_SQRT5 * sh.z);
}

// Propagation sends a cell's light to its 6 neighbours through 5 faces each: 30 faces with
// flux Omega_f * I(w_f). Their sum is the cell's flux, but a 2-band SH has negative lobes, so
// some face fluxes can be negative: sent as they are they are unphysical, clamped they add
// energy, and occluded they add energy too (a blocked negative flux is a gain). So each cell
// sends only its positive face fluxes, all scaled by this factor, which makes them sum to the
// cell's flux again: energy is conserved exactly and nothing negative travels. 1 when no
// face is negative, 0 for a cell with no positive flux.
//
// Closed form rather than 30 clamped faces (propagation runs it for every cell and channel, and
// lavapipe runs every line for every lane), on the sender form e = (A, P) (lpv_sender_form),
// where the faces come in opposite pairs with values A +- u: the far faces along axis a
// (u = sqrt(5) P_a) and the side faces (u = 2 P_i +- P_j, i != j: 12 pairs). For A > 0 a
// pair's positive parts sum to 2A + max(|u| - A, 0), so the positive fluxes are the cell's
// flux, A (6 Omega_f + 24 Omega_s), plus an excess that is zero exactly when no face is
// negative. Over the signs, |2 P_i +- P_j| takes the values 2|P_i| + |P_j| and |2|P_i| - |P_j||.
// No face is negative when sqrt(5) |P| <= A (each |u| is at most sqrt(5) |P|, by
// Cauchy-Schwarz): that test returns first, since Mesa 25's lavapipe skips code that no lane of
// a subgroup runs, and in a propagated grid whole subgroups of cells pass it: without it the
// closed form was slower than the 30 faces on Mesa 25 (docs/lpv.md, "Targets", has the
// numbers and commands).
LPV_FUNC lpv_real lpv_sender_outgoing_scale(vec4 e) {
  const lpv_real mean = e.x;
  const vec3 p = abs(vec3(e.y, e.z, e.w));
  if (!(mean > 0.0f)) return 0.0f;
  if (5.0f * dot(p, p) <= mean * mean) return 1.0f;
  const vec3 twice = lpv_real(2) * p;
  const vec3 next = vec3(p.y, p.z, p.x);  // |P_j|, j = i + 1
  const vec3 prev = vec3(p.z, p.x, p.y);  // j = i + 2
  const vec3 zero = vec3(0.0f);
  const vec3 far_excess = max(LPV_SQRT5 * p - mean, zero);
  const vec3 side_excess = max(twice + next - mean, zero) + max(abs(twice - next) - mean, zero) +
                           max(twice + prev - mean, zero) + max(abs(twice - prev) - mean, zero);
  const lpv_real excess = LPV_FAR_FACE_SOLID_ANGLE * (far_excess.x + far_excess.y + far_excess.z) +
                          LPV_SIDE_FACE_SOLID_ANGLE * (side_excess.x + side_excess.y + side_excess.z);
  const lpv_real total = mean * (6.0f * LPV_FAR_FACE_SOLID_ANGLE + 24.0f * LPV_SIDE_FACE_SOLID_ANGLE);
  return total / (total + excess);
}

// The same for an SH vector.
LPV_FUNC lpv_real lpv_outgoing_scale(vec4 sh) { return lpv_sender_outgoing_scale(lpv_sender_form(sh)); }

#ifdef __cplusplus
}  // namespace gpu or gpu_double
#else
#undef lpv_real
#endif
#undef LPV_FUNC
#undef LPV_CONST_F

#endif  // LPV_SH_BODY
