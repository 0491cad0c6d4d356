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
// Speed: occlusion and bounces are specialization constants, not branches on the frame's
// flags: lavapipe runs both sides of a branch under a lane mask, so a run-time flag would make
// every face pay for the blocking and reflection code (a third of the pass) even when off.
// The first iteration of an occluded frame runs the occluded shader with no blockers (the
// same result up to float rounding: flux * 1), so a frame compiles one variant, not two
// (lavapipe compiles at first use; this shader takes a sixth of a second).
// The 30 faces are written out by macros with their directions and normals as literals
// (lavapipe's compiler does not unroll loops this large), so each face costs one 4-wide dot
// per channel plus two additions (a cosine lobe along an axis has two non-zero terms).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = 1, rgba32f) uniform image3D grids;
layout(set = 0, binding = 2, rgba32f) uniform image3D accumulated_r;
layout(set = 0, binding = 3, rgba32f) uniform image3D accumulated_g;
layout(set = 0, binding = 4, rgba32f) uniform image3D accumulated_b;
layout(set = 0, binding = 5, rgba32f) uniform readonly image3D faces;
layout(std430, set = 0, binding = 6) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { uint cascade; uint stats_record; uint iteration; } push;

// The faces' blocking potentials apply (when the frame has a geometry volume; from the second
// iteration on), and with them the light the blockers reflect (bounces: 2).
layout(constant_id = 0) const bool OCCLUDED = false;
layout(constant_id = 1) const bool BOUNCES = false;

#include "shared/lpv_grid_flux.glsl"

const float S5 = 0.4472135955;  // 1 / sqrt(5)
const float T5 = 0.8944271910;  // 2 / sqrt(5)
// The cells gather in lobe weights, sum of flux * (1, -n.y, n.z, -n.x) over the faces' normals
// n; times LOBE_SCALE that is the sum of the cosine lobes flux/pi * sh_cosine_lobe(n). Adding
// weights costs one addition per face and channel where adding lobes cost a multiplication too.
const vec4 LOBE_SCALE = vec4(SH_COSINE_C0, SH_COSINE_C1, SH_COSINE_C1, SH_COSINE_C1) / LPV_PI;
vec4 lobe_weights(vec3 n) { return vec4(1.0, -n.y, n.z, -n.x); }

// The weight a lobe along each axis adds to its one non-constant term.
#define LOBE_AXIS_PX(sh, flux) sh.w -= (flux)
#define LOBE_AXIS_NX(sh, flux) sh.w += (flux)
#define LOBE_AXIS_PY(sh, flux) sh.y -= (flux)
#define LOBE_AXIS_NY(sh, flux) sh.y += (flux)
#define LOBE_AXIS_PZ(sh, flux) sh.z += (flux)
#define LOBE_AXIS_NZ(sh, flux) sh.z -= (flux)

// dot() as multiply-adds: with a constant basis (a face's, or its reverse for the blockers),
// lavapipe then drops the terms that are zero, which it keeps in dot(): about 130 fewer of
// the shader's some 4400 instructions (counted in gdb's disassembly of the JIT code, the
// pages scripts/profile-jit.sh finds).
float fdot(vec4 a, vec4 b) { return fma(a.x, b.x, fma(a.y, b.y, fma(a.z, b.z, a.w * b.w))); }

// One face: flux Omega * I(w) of each channel through it (less what the blockers stop), into
// this cell as a cosine lobe along the face's normal axis. Omega is folded into the basis,
// a constant: Omega * max(0, x) = max(0, Omega * x).
#define FACE(W, OMEGA, AXIS)                                                                        \
  {                                                                                                 \
    const vec4 basis = (OMEGA) * sh_basis(W);                                                       \
    vec3 flux = max(vec3(fdot(sh_r, basis), fdot(sh_g, basis), fdot(sh_b, basis)), vec3(0.0));       \
    if (OCCLUDED) flux *= transmitted(blocking, albedo, W, flux, gathered);                        \
    gathered[0].x += flux.r;                                                                        \
    gathered[1].x += flux.g;                                                                        \
    gathered[2].x += flux.b;                                                                        \
    LOBE_AXIS_##AXIS(gathered[0], flux.r);                                                          \
    LOBE_AXIS_##AXIS(gathered[1], flux.g);                                                          \
    LOBE_AXIS_##AXIS(gathered[2], flux.b);                                                          \
  }

// The fraction of `flux` (travelling along w) the blockers on the face let through. With
// bounces, the light they stop is reflected back, diffusely around their mean normal.
float transmitted(vec4 blocking, vec3 albedo, vec3 w, vec3 flux, inout vec4 gathered[3]) {
  float blocked = clamp(fdot(blocking, sh_basis(-w)), 0.0, 1.0);
  if (BOUNCES && albedo != vec3(0.0) && blocked > 0.0) {
    vec3 mean_normal = vec3(-blocking.w, -blocking.y, blocking.z);
    vec4 weights = lobe_weights(dot(mean_normal, mean_normal) > 0.0 ? normalize(mean_normal) : -w);
    vec3 reflected = flux * blocked * albedo;
    gathered[0] += reflected.r * weights;
    gathered[1] += reflected.g * weights;
    gathered[2] += reflected.b * weights;
  }
  return 1.0 - blocked;
}

// The light of the neighbour at cell - STEP, travelling along +STEP: its far face (normal
// along the travel) and its four side faces (normals across it). A neighbour past the grid's
// edge sends nothing: it is read at the nearest cell and weighted by zero, which lavapipe runs
// faster than a branch around the whole neighbour (both sides of a branch run under a mask).
#define NEIGHBOUR(STEP, AXIS_INDEX, FAR, W_FAR, S1, W1, S2, W2, S3, W3, S4, W4)                    \
  {                                                                                                 \
    ivec3 neighbour = cell - STEP;                                                                  \
    float inside = all(greaterThanEqual(neighbour, ivec3(0))) && all(lessThan(neighbour, dims)) ? 1.0 : 0.0; \
    neighbour = clamp(neighbour, ivec3(0), dims - 1);                                               \
    vec4 sh_r = imageLoad(grids, lpv_grid_texel(neighbour, 0, source, depth)) * inside;             \
    vec4 sh_g = imageLoad(grids, lpv_grid_texel(neighbour, 1, source, depth)) * inside;             \
    vec4 sh_b = imageLoad(grids, lpv_grid_texel(neighbour, 2, source, depth)) * inside;             \
    vec4 blocking = vec4(0.0);                                                                      \
    vec3 albedo = vec3(0.0);                                                                        \
    if (OCCLUDED) {                                                                                 \
      ivec3 lower = min(cell, neighbour);                                                           \
      blocking = imageLoad(faces, ivec3(6 * lower.x + AXIS_INDEX, lower.yz)) * blocking_on;         \
      if (BOUNCES) albedo = imageLoad(faces, ivec3(6 * lower.x + 3 + AXIS_INDEX, lower.yz)).rgb;    \
    }                                                                                               \
    FACE(W_FAR, LPV_FAR_FACE_SOLID_ANGLE, FAR)                                                      \
    FACE(W1, LPV_SIDE_FACE_SOLID_ANGLE, S1)                                                         \
    FACE(W2, LPV_SIDE_FACE_SOLID_ANGLE, S2)                                                         \
    FACE(W3, LPV_SIDE_FACE_SOLID_ANGLE, S3)                                                         \
    FACE(W4, LPV_SIDE_FACE_SOLID_ANGLE, S4)                                                         \
  }

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  ivec3 dims = ivec3(g.dims.xyz);
  // Invocations past the grid (dims not a multiple of the group) work on its last cell and
  // store nothing.
  bool in_grid = all(lessThan(gl_GlobalInvocationID, uvec3(dims)));
  ivec3 cell = min(ivec3(gl_GlobalInvocationID), dims - 1);
  uint depth = g.dims.z;
  uint source = (push.iteration + 1u) & 1u;  // iteration 1 reads grid 0 and writes grid 1
  uint target = push.iteration & 1u;
  float blocking_on = push.iteration >= 2u ? 1.0 : 0.0;

  vec4 gathered[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  NEIGHBOUR(ivec3(1, 0, 0), 0, PX, vec3(1, 0, 0), PY, vec3(T5, S5, 0), NY, vec3(T5, -S5, 0), PZ, vec3(T5, 0, S5),
            NZ, vec3(T5, 0, -S5))
  NEIGHBOUR(ivec3(-1, 0, 0), 0, NX, vec3(-1, 0, 0), PY, vec3(-T5, S5, 0), NY, vec3(-T5, -S5, 0), PZ,
            vec3(-T5, 0, S5), NZ, vec3(-T5, 0, -S5))
  NEIGHBOUR(ivec3(0, 1, 0), 1, PY, vec3(0, 1, 0), PX, vec3(S5, T5, 0), NX, vec3(-S5, T5, 0), PZ, vec3(0, T5, S5),
            NZ, vec3(0, T5, -S5))
  NEIGHBOUR(ivec3(0, -1, 0), 1, NY, vec3(0, -1, 0), PX, vec3(S5, -T5, 0), NX, vec3(-S5, -T5, 0), PZ,
            vec3(0, -T5, S5), NZ, vec3(0, -T5, -S5))
  NEIGHBOUR(ivec3(0, 0, 1), 2, PZ, vec3(0, 0, 1), PX, vec3(S5, 0, T5), NX, vec3(-S5, 0, T5), PY, vec3(0, S5, T5),
            NY, vec3(0, -S5, T5))
  NEIGHBOUR(ivec3(0, 0, -1), 2, NZ, vec3(0, 0, -1), PX, vec3(S5, 0, -T5), NX, vec3(-S5, 0, -T5), PY,
            vec3(0, S5, -T5), NY, vec3(0, -S5, -T5))

  for (int c = 0; c < 3; ++c) gathered[c] *= LOBE_SCALE;

  vec3 flux = vec3(0.0);
  if (in_grid) {
    // What this cell sends in the next iteration: its SH times the outgoing scale, so that its
    // face fluxes, negative ones dropped, add up to its flux (see lpv_outgoing_scale).
    for (int c = 0; c < 3; ++c) {
      imageStore(grids, lpv_grid_texel(cell, c, target, depth), gathered[c] * lpv_outgoing_scale(gathered[c]));
      flux[c] = sh_flux(gathered[c]);
    }
    ivec3 texel = lpv_accumulated_texel(cell, push.cascade, depth);
    imageStore(accumulated_r, texel, imageLoad(accumulated_r, texel) + gathered[0]);
    imageStore(accumulated_g, texel, imageLoad(accumulated_g, texel) + gathered[1]);
    imageStore(accumulated_b, texel, imageLoad(accumulated_b, texel) + gathered[2]);
  }
  add_grid_flux(flux, push.stats_record, lpv.scales.x);
}
