#version 450
// Linear image -> 8-bit RGBA for display: optional tone curve, clamp, sRGB transfer.
// Data views (normal, depth) are quantised linearly instead.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"

layout(local_size_x = SHADE_GROUP_X, local_size_y = SHADE_GROUP_Y) in;

layout(std430, set = 0, binding = 0) readonly buffer Linear { vec4 linear_pixels[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Display { uint display_pixels[]; };
layout(push_constant) uniform Params { GpuTonemapParams params; };

vec3 tone_curve(vec3 x, uint curve) {
  if (curve == TONEMAP_REINHARD) return x / (1.0 + x);
  if (curve == TONEMAP_ACES) return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);  // Narkowicz fit
  return x;
}

vec3 srgb_encode(vec3 c) {
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  uvec2 size = params.size_mode.xy;
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  uint index = pixel.y * size.x + pixel.x;

  vec3 c = max(linear_pixels[index].rgb, vec3(0.0));
  if (params.size_mode.w == 1u) c = srgb_encode(clamp(tone_curve(c, params.size_mode.z), 0.0, 1.0));
  uvec3 q = uvec3(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  display_pixels[index] = q.r | (q.g << 8) | (q.b << 16) | (255u << 24);
}
