#version 450
// Geometry volume, step 3: for each cell, the blocking potential on its +X, +Y and +Z faces
// (its SH and spread), the mean of each face's four corners. Propagation between two
// neighbouring cells reads the face they share. Also the blockers' mean albedo per face, for
// the light they reflect, and the walls located about its +X, +Y and +Z faces, with whether its
// centre lies inside a thin solid (lpv_walls.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/geometry_volume_interface.h"
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_gather.h"
#include "shared/lpv_walls.h"
#include "shared/lpv_grid.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = GEOMETRY_RESOLVE_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = GEOMETRY_RESOLVE_CORNERS, rgba32f) uniform readonly imageBuffer corners;  // LPV_GV_CORNER_TEXELS per corner
layout(std430, set = 0, binding = GEOMETRY_RESOLVE_FACES) writeonly buffer Faces { u64vec2 faces[]; };
layout(std430, set = 0, binding = GEOMETRY_RESOLVE_FACE_ALBEDO) writeonly buffer FaceAlbedo { u64vec2 face_albedo[]; };
layout(std430, set = 0, binding = GEOMETRY_RESOLVE_FACE_COVER) writeonly buffer FaceCover { u64vec2 face_cover[]; };
// Texel cascade * cells + cell: the walls located about its +X, +Y, +Z faces (lpv_walls_to_unorm),
// and in w's low byte how much its centre lies inside a thin solid (lpv_wall_inside).
layout(std430, set = 0, binding = GEOMETRY_RESOLVE_WALLS) writeonly buffer Walls { uvec4 walls[]; };
layout(push_constant) uniform Push { GeometryResolvePush push; };
// The blockers' albedo serves bounces only: without them its faces are not written.
layout(constant_id = 0) const bool BOUNCES = true;
// The gather pairs its lines' faces (lpv.line_blocking "paired" or "located"): each face's
// cover texel (lpv_gather_cover_texel), so that its walk reads one texel a face, not two.
layout(constant_id = 1) const bool COVERS = true;
// The walls are located (lpv.line_blocking "located"): every cell's walls texel, which the
// injection and the shading read, and the cover texels scaled to the walls nearest their plane.
layout(constant_id = 2) const bool WALLS = true;

// Texel k of the face in the plane of corners `plane` along `axis`, at the cell's place across
// it: the mean of its four corners' (LPV_GV_CORNER_TEXELS a corner). The cell's +axis face lies
// in plane cell[axis] + 1.
vec4 face_mean(ivec3 cell, int axis, int plane, uvec3 dims, int k) {
  int u = (axis + 1) % 3;
  int v = (axis + 2) % 3;
  vec4 mean = vec4(0.0);
  for (int c = 0; c < 4; ++c) {
    ivec3 corner = cell;
    corner[axis] = plane;
    corner[u] += c & 1;
    corner[v] += c >> 1;
    mean += 0.25 * imageLoad(corners, int(LPV_GV_CORNER_TEXELS * lpv_cell_index(uvec3(corner), dims + 1u)) + k);
  }
  return mean;
}

// The covers across `axis` (lpv_wall_plane_covers: facing + and -) of a face with the blocking
// SH `sh` and spread `spread`.
vec2 face_covers(vec4 sh, vec4 spread, int axis) {
  return lpv_wall_plane_covers(lpv_gather_first_moment(sh)[axis], spread[axis]);
}
// And of the face in plane `plane`: none past the lattice.
vec2 plane_covers(ivec3 cell, int axis, int plane, uvec3 dims) {
  if (plane < 0 || plane > int(dims[axis])) return vec2(0.0);
  return face_covers(face_mean(cell, axis, plane, dims, 0), face_mean(cell, axis, plane, dims, 1), axis);
}

// The walls about a plane (lpv_walls.h: xy facing +, zw facing -), from the covers of the planes
// below it, at it and above it (each lpv_wall_plane_covers').
vec4 walls_about(vec2 below, vec2 at, vec2 above) {
  return vec4(lpv_wall_locate(below.x, at.x, above.x), lpv_wall_locate(below.y, at.y, above.y));
}
// The walls packed as a texel's word keeps them (a byte each), and as its readers get them back.
uint packed_walls(vec4 walls) { return packUnorm4x8(lpv_walls_to_unorm(walls)); }
vec4 kept_walls(uint packed) { return lpv_walls_from_unorm(unpackUnorm4x8(packed)); }

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  uvec3 dims = lpv.cascades[push.cascade].dims.xyz;
  if (any(greaterThanEqual(cell, ivec3(dims)))) return;
  uvec4 located = uvec4(0u);
  float inside = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    int plane = cell[axis] + 1;  // the +axis face's
    vec4 sh = face_mean(cell, axis, plane, dims, 0);
    vec4 spread = face_mean(cell, axis, plane, dims, 1);
    vec4 albedo = BOUNCES ? face_mean(cell, axis, plane, dims, 2) : vec4(0.0);
    faces[lpv_face_texel(cell, axis, dims)] = texel_bits(sh);
    faces[lpv_face_spread_texel(cell, axis, dims)] = texel_bits(spread);
    vec4 cover = lpv_gather_cover_texel(sh, spread.xyz, axis);
    if (WALLS) {
      // The walls about this face, located from its plane and the planes of corners either side.
      vec2 below = plane_covers(cell, axis, plane - 1, dims);
      vec2 at = face_covers(sh, spread, axis);
      vec2 above = plane_covers(cell, axis, plane + 1, dims);
      located[axis] = packed_walls(walls_about(below, at, above));
      // The walls as the texel keeps them, which the CPU reference reads back (tests/lpv).
      vec4 upper = kept_walls(located[axis]);
      cover *= lpv_wall_share(upper, at.x + at.y);
      // And those about the -axis face, as the cell below keeps them, for the centre between.
      vec4 lower = kept_walls(packed_walls(walls_about(plane_covers(cell, axis, plane - 2, dims), below, at)));
      inside = max(inside, lpv_wall_inside(lower, upper));
    }
    if (COVERS) face_cover[lpv_face_cover_texel(cell, axis, dims)] = texel_bits(cover);
    if (BOUNCES)
      face_albedo[lpv_face_albedo_texel(cell, axis, dims)] = texel_bits(vec4(albedo.w > 0.0 ? albedo.rgb / albedo.w : vec3(0.0), 0.0));
  }
  if (WALLS) {
    located.w = packUnorm4x8(vec4(inside, 0.0, 0.0, 0.0));
    walls[lpv_accumulated_texel(cell, push.cascade, dims)] = located;
  }
}
