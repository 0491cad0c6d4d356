#version 450
// The forward pass: direct and indirect light shaded while rasterising, straight into the
// 8-bit display image, for frames that show the final or direct view and need no linear image
// (a PNG). The same light (shared/direct_light.glsl, shared/lpv_irradiance.glsl) and encoding
// (shared/display_encode.glsl) as the deferred shading, from the interpolated surface instead
// of the G-buffer's stored one. Why a second way to shade: on lavapipe the fragment stage runs
// the lighting in about a third of the time the compute shading takes, and the frame writes
// one 4-byte target instead of the G-buffer's 32 bytes a pixel and reads none of it back.
#extension GL_GOOGLE_include_directive : require
#include "shared/camera_raster_interface.h"
#include "shared/gpu_types.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/material_surface.glsl"

layout(constant_id = 2) const uint LIGHT_KINDS = LIGHTS_ALL;  // LIGHTS_* bits of this frame's lights
layout(constant_id = 3) const uint LIGHT_COUNT = SHADE_LIGHTS_FROM_FRAME;
layout(constant_id = 4) const uint TONE_CURVE = TONEMAP_NONE;
layout(constant_id = 5) const uint CASCADES = 0u;  // of indirect light; 0: none

layout(std140, set = 0, binding = CAMERA_FRAME) uniform Frame { GpuFrame frame; };
layout(set = 0, binding = FORWARD_SHADOW_MAPS) uniform sampler2DArray shadow_maps;
// Uniform buffers, not storage buffers: lavapipe loads a fragment shader's storage buffer lane
// by lane even at an address all lanes share, a uniform buffer once (the pass 5.8 -> 5.1 ms
// at 512^2). The buffers are sized for the most lights and views a frame may have.
layout(std140, set = 0, binding = FORWARD_LIGHTS) uniform Lights { GpuLight lights[SHADE_MAX_LIGHTS]; };
layout(std140, set = 0, binding = FORWARD_SHADOW_VIEWS) uniform ShadowViews { GpuShadowView shadow_views[SHADE_MAX_SHADOW_VIEWS]; };
layout(std140, set = 0, binding = FORWARD_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = FORWARD_ACCUMULATED_R, rgba32f) uniform readonly imageBuffer accumulated_r;
layout(set = 0, binding = FORWARD_ACCUMULATED_G, rgba32f) uniform readonly imageBuffer accumulated_g;
layout(set = 0, binding = FORWARD_ACCUMULATED_B, rgba32f) uniform readonly imageBuffer accumulated_b;
layout(set = 0, binding = FORWARD_WALLS, rgba32ui) uniform readonly uimageBuffer walls;
#include "shared/direct_light.glsl"
#include "shared/lpv_irradiance.glsl"
#include "shared/display_encode.glsl"

layout(location = 0) out vec4 out_display;  // an R8G8B8A8_UNORM target: the encoded bytes exactly

void main() {
  vec3 n, albedo;
  material_surface(n, albedo);
  vec3 emitted = ANY_EMISSIVE ? draw.material.emissive.rgb : vec3(0.0);
  vec3 e = direct_irradiance(in_world, n);
  if (CASCADES > 0u) e += lpv.scales.z * indirect_irradiance(in_world, n);
  vec3 radiance = (albedo / LPV_PI * e + emitted) * frame.exposure.x;
  out_display = unpackUnorm4x8(display_pixel(radiance, true, TONE_CURVE));
}
