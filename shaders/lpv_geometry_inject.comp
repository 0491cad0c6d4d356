#version 450
// Geometry volume, step 1: surfels add their blocking potential to the cell corners around them.
// A surfel of area A with normal n has the blocking potential p = A / s^2 on a cell face of
// side s: the fraction of light travelling along w it stops is p <n, -w> (one-sided, the
// cosine lobe of the SH; LPV annotations 5.1) or p |<n, w>| (projected, from the SH's first
// moment and, where both sides of a wall cancel there, the spread p |n|; lpv_sh.h). Surfels
// come from the RSMs (every light view), from the camera's surfel G-buffer, or from the
// scene's surfaces themselves (the blockers, cut from its triangles once); each source has
// its own slot of sums, so the same wall held by two is not counted twice (the resolve takes
// the strongest source per corner).
#extension GL_GOOGLE_include_directive : require
#include "shared/albedo_code.h"
#include "shared/geometry_volume_interface.h"
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_VPL_GROUP, local_size_y = LPV_VPL_GROUP) in;

layout(std140, set = 0, binding = GEOMETRY_INJECT_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = GEOMETRY_INJECT_RSM_POSITION, rgba32f) uniform readonly image2DArray rsm_position;
layout(set = 0, binding = GEOMETRY_INJECT_RSM_NORMAL, rgba32f) uniform readonly image2DArray rsm_normal;
layout(set = 0, binding = GEOMETRY_INJECT_RSM_FLUX, rgba32f) uniform readonly image2DArray rsm_flux;
// The camera's surfel G-buffer (FrameTargets::surfels): a texel per stride x stride pixels.
layout(set = 0, binding = GEOMETRY_INJECT_CAMERA_POSITION, rgba32f) uniform readonly image2D g_position;
layout(set = 0, binding = GEOMETRY_INJECT_CAMERA_NORMAL, rgba16f) uniform readonly image2D g_normal;
layout(set = 0, binding = GEOMETRY_INJECT_CAMERA_ALBEDO, rgba16f) uniform readonly image2D g_albedo;
// lpv_gv_corner_words per corner and slot, `slots` slots a corner.
layout(std430, set = 0, binding = GEOMETRY_INJECT_CORNER_SUMS) buffer CornerSums { int64_t corner_sums[]; };
layout(std430, set = 0, binding = GEOMETRY_INJECT_BLOCKERS) readonly buffer Blockers { GpuBlocker blockers[]; };
// The scene source: how many blockers, each invocation taking one (LPV_BLOCKER_GROUP a group).
layout(push_constant) uniform Push { GeometryInjectPush push; };

// Surfels seen edge-on count at most this many times their projected area.
const float MIN_AREA_COSINE = 0.25;
// One surfel blocks at most this many cell faces (keeps the fixed point far from overflow).
const float MAX_POTENTIAL = 64.0;

// The blockers' albedo serves bounces only: without them it is neither summed nor splatted.
layout(constant_id = 1) const bool BOUNCES = true;

// The lattice is the cell corners; each holds lpv_gv_corner_words sums per slot (gpu_types.h).
#define SPLAT_VALUES LPV_GV_WORDS
#define SPLAT_ACTIVE_VALUES lpv_gv_corner_words(BOUNCES)
#define SPLAT_SUMS corner_sums
uint splat_index(ivec3 corner) {
  uvec3 corner_dims = lpv.cascades[push.cascade].dims.xyz + 1u;
  return (lpv_cell_index(uvec3(corner), corner_dims) * push.slots + push.slot) * SPLAT_ACTIVE_VALUES;
}
#include "shared/lpv_splat.glsl"

// Split over the 8 corners around p with trilinear weights, so the volume changes
// continuously as surfels move (a camera or light moved by a hair must not make it jump).
// False when the surfel adds nothing to this cascade.
bool surfel_splat(vec3 p, vec3 n, float area, vec3 albedo, out ivec3 low, out vec3 f, out float values[SPLAT_VALUES]) {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  float s = g.origin.w;
  vec3 q = lpv_grid_position(g, p);
  float potential = min(area / (s * s), MAX_POTENTIAL);
  vec4 lobe = sh_cosine_lobe(n);
  for (uint k = 0u; k < 4u; ++k) values[k] = lobe[k] * potential;
  // The spread p |n| (lpv_closed_blocking), which both sides of a wall add to alike.
  for (uint k = 0u; k < 3u; ++k) values[LPV_GV_SPREAD + k] = abs(n[k]) * potential;
  values[LPV_GV_SPREAD + 3u] = 0.0;
  if (BOUNCES) {
    for (uint c = 0u; c < 3u; ++c) values[LPV_GV_ALBEDO + c] = albedo[c] * potential;
    values[LPV_GV_ALBEDO + 3u] = potential;
  }
  splat_lattice(q, low, f);  // lattice: cell corners
  return lpv_inside_distance(g, q) >= 0.0 && potential > 0.0;
}

void main() {
  uvec3 id = splat_group_point();
  bool found = false;
  vec3 position = vec3(0.0);
  vec3 normal = vec3(0.0, 0.0, 1.0);
  float area = 0.0;
  vec3 albedo = vec3(0.0);
  if (push.source == LPV_GV_SOURCE_RSM) {
    // Every stride-th texel of the RSM, standing for stride^2 texels.
    uint stride = push.rsm_stride;
    uint res = push.rsm_side;
    ivec3 texel = ivec3(id.xy * stride + stride / 2u, push.rsm_layer);
    if (texel.x < res && texel.y < res) {
      vec4 p = imageLoad(rsm_position, texel);
      vec4 n = imageLoad(rsm_normal, texel);
      found = p.w != 0.0;
      position = p.xyz;
      normal = n.xyz;
      area = imageLoad(rsm_flux, texel).w * float(stride * stride);
      albedo = albedo_decode(n.w);
    }
  } else if (push.source == LPV_GV_SOURCE_SCENE) {
    // A piece of a scene surface: consecutive ones lie close together (pieces of one triangle),
    // as splat_subgroup wants.
    uint index = gl_WorkGroupID.x * LPV_BLOCKER_GROUP + gl_LocalInvocationIndex;
    if (index < push.blocker_count) {
      GpuBlocker b = blockers[index];
      found = true;
      position = b.position.xyz;
      normal = b.normal.xyz;
      area = b.position.w;
      albedo = albedo_decode(b.normal.w);
    }
  } else {
    // A texel of the camera's surfel G-buffer, standing for stride^2 pixels of the image.
    uint stride = lpv.sizes.z;
    ivec2 size = imageSize(g_position);
    ivec2 pixel = ivec2(id.xy);
    if (pixel.x < size.x && pixel.y < size.y) {
      vec4 p = imageLoad(g_position, pixel);
      found = p.w != 0.0;
      position = p.xyz;
      normal = imageLoad(g_normal, pixel).xyz;
      vec3 to_camera = lpv.camera.yzw - position;
      float dist2 = dot(to_camera, to_camera);
      float side = lpv.camera.x * float(stride);  // the pixels' footprint at unit distance
      float projected_area = side * side * dist2;
      float cos_view = abs(dot(normalize(normal), to_camera)) * inversesqrt(max(dist2, 1e-30));
      area = projected_area / max(cos_view, MIN_AREA_COSINE);
      albedo = imageLoad(g_albedo, pixel).rgb;
    }
  }
  found = found && dot(normal, normal) > 0.0;
  ivec3 low;
  vec3 f;
  float values[SPLAT_VALUES];
  bool adds = surfel_splat(position, found ? normalize(normal) : vec3(0.0, 0.0, 1.0), area, albedo, low, f, values);
  splat_subgroup(found && adds, low, f, values, ivec3(lpv.cascades[push.cascade].dims.xyz), lpv.scales.y,
                 SPLAT_UNWEIGHED);
}
