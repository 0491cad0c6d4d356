#version 450
// Geometry volume, step 1: surfels add their blocking potential to the cell corners around them.
// A surfel of area A with normal n blocks the fraction A / s^2 * max(0, <n, -w>) of light
// travelling in direction w across a cell face of side s: one-sided, since a two-sided
// surfel cancels in 2-band SH (LPV annotations 5.1). Surfels come from the RSMs (every light
// view) and from the camera's G-buffer; each source has its own accumulators, so the same
// wall seen by both is not counted twice (the resolve takes the stronger source per corner).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_VPL_GROUP, local_size_y = LPV_VPL_GROUP) in;

layout(std140, set = 0, binding = 0) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2DArray rsm_position;
layout(set = 0, binding = 2, rgba32f) uniform readonly image2DArray rsm_normal;
layout(set = 0, binding = 3, rgba32f) uniform readonly image2DArray rsm_flux;
layout(set = 0, binding = 4, rgba32f) uniform readonly image2D g_position;
layout(set = 0, binding = 5, rgba16f) uniform readonly image2D g_normal;
layout(set = 0, binding = 6, rgba16f) uniform readonly image2D g_albedo;
layout(std430, set = 0, binding = 7) buffer CornerSums { int64_t corner_sums[]; };  // LPV_GV_WORDS per corner, source
layout(push_constant) uniform Push { uint cascade; uint source; } push;

// Surfels seen edge-on count at most this many times their projected area.
const float MIN_AREA_COSINE = 0.25;
// One surfel blocks at most this many cell faces (keeps the fixed point far from overflow).
const float MAX_POTENTIAL = 64.0;

vec3 decode_albedo(float code) {
  uint q = uint(code);
  return vec3(q & 255u, (q >> 8) & 255u, (q >> 16) & 255u) / 255.0;
}

// lpv.injection "nearest": each surfel to its nearest corner only (cheaper, not continuous).
layout(constant_id = 0) const bool TRILINEAR_INJECTION = true;

// Split over the 8 corners around p with trilinear weights, so the volume changes
// continuously as surfels move (a camera or light moved by a hair must not make it jump).
void add_surfel(vec3 p, vec3 n, float area, vec3 albedo) {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  float s = g.origin.w;
  vec3 q = lpv_grid_position(g, p);
  if (any(lessThan(q, vec3(0.0))) || any(greaterThan(q, vec3(g.dims.xyz)))) return;
  float potential = min(area / (s * s), MAX_POTENTIAL);
  if (!(potential > 0.0)) return;
  uvec3 corner_dims = g.dims.xyz + 1u;
  ivec3 low = TRILINEAR_INJECTION ? ivec3(floor(q)) : ivec3(round(q));
  vec3 f = q - vec3(low);
  vec4 lobe = sh_cosine_lobe(n);
  float units = lpv.scales.y;
  for (uint i = 0u; i < (TRILINEAR_INJECTION ? 8u : 1u); ++i) {
    ivec3 o = ivec3(i & 1u, (i >> 1u) & 1u, i >> 2u);
    vec3 w3 = mix(1.0 - f, f, vec3(o));
    float share = TRILINEAR_INJECTION ? potential * w3.x * w3.y * w3.z : potential;
    if (share == 0.0) continue;
    uvec3 corner = uvec3(clamp(low + o, ivec3(0), ivec3(g.dims.xyz)));
    uint base = (lpv_cell_index(corner, corner_dims) * LPV_GV_SOURCES + push.source) * LPV_GV_WORDS;
    for (uint k = 0u; k < 4u; ++k) atomicAdd(corner_sums[base + k], to_fixed(lobe[k] * share, units));
    for (uint c = 0u; c < 3u; ++c) atomicAdd(corner_sums[base + 4u + c], to_fixed(albedo[c] * share, units));
    atomicAdd(corner_sums[base + 7u], to_fixed(share, units));
  }
}

void main() {
  uvec3 id = gl_GlobalInvocationID;
  if (push.source == LPV_GV_SOURCE_RSM) {
    uint res = lpv.sizes.x;
    if (id.x >= res || id.y >= res) return;
    ivec3 texel = ivec3(id);
    vec4 position = imageLoad(rsm_position, texel);
    if (position.w == 0.0) return;
    vec4 normal = imageLoad(rsm_normal, texel);
    add_surfel(position.xyz, normalize(normal.xyz), imageLoad(rsm_flux, texel).w, decode_albedo(normal.w));
  } else {
    // Every stride-th pixel of the camera's G-buffer, standing for stride^2 pixels.
    uint stride = lpv.sizes.z;
    ivec2 size = imageSize(g_position);
    ivec2 pixel = ivec2(id.xy * stride + stride / 2u);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    vec4 position = imageLoad(g_position, pixel);
    if (position.w == 0.0) return;
    vec3 n = normalize(imageLoad(g_normal, pixel).xyz);
    vec3 to_camera = lpv.camera.yzw - position.xyz;
    float dist2 = dot(to_camera, to_camera);
    float side = lpv.camera.x * float(stride);  // the pixels' footprint at unit distance
    float projected_area = side * side * dist2;
    float cos_view = abs(dot(n, to_camera)) * inversesqrt(max(dist2, 1e-30));
    add_surfel(position.xyz, n, projected_area / max(cos_view, MIN_AREA_COSINE), imageLoad(g_albedo, pixel).rgb);
  }
}
