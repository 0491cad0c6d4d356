#version 450
// Shading of the G-buffer: direct light from punctual lights with shadow maps, plus the
// indirect light of the Light Propagation Volumes. Outputs, as the frame asks: one linear
// RGBA float per pixel (radiance * 2^exposure for the lit views, the raw quantity for the
// data views) and one display-encoded RGBA8 pixel. Encoding here instead of in a pass of
// its own saves that pass's reading back of the linear image: 1.9 ms of a 512^2 frame on
// lavapipe, and a PNG frame writes no linear image at all.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/shade_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"

layout(local_size_x = SHADE_GROUP_X, local_size_y = SHADE_GROUP_Y) in;

// Specialised per frame: lavapipe runs both sides of a branch under a lane mask, so code for
// what the frame does not have (the indirect light without a grid, the other views, the
// kinds of light source it lacks) would cost every pixel. The cascade count makes the
// cascade loops ones of constant length, which the compiler unrolls: with one cascade at
// 512x512 the pass took 12.5 -> 9.0 ms (commit e70855a).
layout(constant_id = 0) const uint CASCADES = 1u;  // of indirect light; 0: none
const bool WITH_INDIRECT = CASCADES > 0u;
layout(constant_id = 1) const uint VIEW = VIEW_FINAL;  // VIEW_*
layout(constant_id = 2) const uint LIGHT_KINDS = LIGHTS_ALL;  // LIGHTS_* bits of this frame's lights
// The number of lights, or SHADE_LIGHTS_FROM_FRAME: a loop of constant length is unrolled
// and reads each light at a constant offset (direct shading 5.7 -> 4.5 ms at 512x512,
// commit 9af103d).
layout(constant_id = 3) const uint LIGHT_COUNT = SHADE_LIGHTS_FROM_FRAME;
layout(constant_id = 4) const uint OUTPUTS = SHADE_OUTPUT_LINEAR;  // SHADE_OUTPUT_* bits
layout(constant_id = 5) const uint TONE_CURVE = TONEMAP_NONE;      // of the display image

layout(std140, set = 0, binding = SHADE_FRAME) uniform Frame { GpuFrame frame; };
layout(set = 0, binding = SHADE_G_POSITION, rgba32f) uniform readonly image2D g_position;
layout(set = 0, binding = SHADE_G_NORMAL, rgba16f) uniform readonly image2D g_normal;
layout(set = 0, binding = SHADE_G_ALBEDO, rgba16f) uniform readonly image2D g_albedo;
layout(set = 0, binding = SHADE_SHADOW_MAPS) uniform sampler2DArray shadow_maps;
layout(std430, set = 0, binding = SHADE_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = SHADE_SHADOW_VIEWS) readonly buffer ShadowViews { GpuShadowView shadow_views[]; };
layout(std430, set = 0, binding = SHADE_MATERIALS) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = SHADE_LINEAR) writeonly buffer Linear { vec4 linear_pixels[]; };
layout(std140, set = 0, binding = SHADE_LPV) uniform Lpv { GpuLpv lpv; };
// Read with imageLoad and filtered here: lavapipe's trilinear sampler lookups cost more than
// the eight loads and weights written out (the pass took 19 ms at 512^2 with them, 17 without,
// when this was changed).
layout(set = 0, binding = SHADE_ACCUMULATED_R, rgba32f) uniform readonly imageBuffer accumulated_r;
layout(set = 0, binding = SHADE_ACCUMULATED_G, rgba32f) uniform readonly imageBuffer accumulated_g;
layout(set = 0, binding = SHADE_ACCUMULATED_B, rgba32f) uniform readonly imageBuffer accumulated_b;
layout(set = 0, binding = SHADE_WALLS, rgba32ui) uniform readonly uimageBuffer walls;
layout(std430, set = 0, binding = SHADE_DISPLAY) writeonly buffer Display { uint display_pixels[]; };
#include "shared/direct_light.glsl"
#include "shared/display_encode.glsl"
#include "shared/lpv_irradiance.glsl"

// The grid itself: the mean radiance (W/(m^2 sr)) of the nearest cell of the finest cascade
// holding p, so cells show as blocks.
vec3 lpv_cell_view(vec3 p) {
  for (uint c = 0u; c < CASCADES; ++c) {
    GpuLpvCascade g = lpv.cascades[c];
    vec3 q = lpv_grid_position(g, p);
    if (lpv_inside_distance(g, q) < 0.0) continue;
    return cell_mean_radiance(c, ivec3(min(uvec3(q), g.dims.xyz - 1u)));
  }
  return vec3(0.0);
}

// What the frame shows at a pixel: a lit view's radiance * 2^exposure, or a data view's value;
// alpha is the coverage, 0 where no surface is (black background).
vec4 view_value(uvec2 pixel) {
  vec4 position = imageLoad(g_position, ivec2(pixel));
  if (position.w == 0.0) return vec4(0.0);
  vec3 p = position.xyz;
  vec3 n = normalize(imageLoad(g_normal, ivec2(pixel)).xyz);
  vec3 albedo = imageLoad(g_albedo, ivec2(pixel)).rgb;
  uint material = uint(position.w) - 1u;

  const uint view = VIEW;
  if (view == VIEW_ALBEDO) return vec4(albedo, 1.0);
  if (view == VIEW_NORMAL) return vec4(n * 0.5 + 0.5, 1.0);
  if (view == VIEW_DEPTH) {
    float depth = dot(p - frame.camera_position.xyz, frame.camera_forward.xyz);
    return vec4(vec3(clamp((depth - frame.depth_range.x) / (frame.depth_range.y - frame.depth_range.x), 0.0, 1.0)), 1.0);
  }
  if (view == VIEW_LPV) return vec4(WITH_INDIRECT ? lpv_cell_view(p) * frame.exposure.x : vec3(0.0), 1.0);
  vec3 e = view != VIEW_INDIRECT ? direct_irradiance(p, n) : vec3(0.0);
  if (WITH_INDIRECT && view != VIEW_DIRECT) e += lpv.scales.z * indirect_irradiance(p, n);
  vec3 emitted = ANY_EMISSIVE && view != VIEW_INDIRECT ? materials[material].emissive.rgb : vec3(0.0);
  return vec4((albedo / LPV_PI * e + emitted) * frame.exposure.x, 1.0);
}

void main() {
  uvec2 size = frame.size_view.xy;
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  uint index = pixel.y * size.x + pixel.x;
  vec4 value = view_value(pixel);
  if ((OUTPUTS & SHADE_OUTPUT_LINEAR) != 0u) linear_pixels[index] = value;
  if ((OUTPUTS & SHADE_OUTPUT_DISPLAY) != 0u)
    display_pixels[index] = display_pixel(value.rgb, VIEW != VIEW_NORMAL && VIEW != VIEW_DEPTH, TONE_CURVE);
}
