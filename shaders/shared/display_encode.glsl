// Linear value -> one 8-bit RGBA pixel for display: optional tone curve, clamp, sRGB transfer
// (display_transfer.h, which the CPU's pictures of linear images use too: lab/accuracy/
// display_image.cpp). Data views (normal, depth) are quantised linearly instead.
#ifndef LPV_DISPLAY_ENCODE_GLSL
#define LPV_DISPLAY_ENCODE_GLSL

#include "display_transfer.h"

// `picture`: tone curve and sRGB; else the value is data, quantised linearly. Negative and NaN
// components are black.
uint display_pixel(vec3 linear, bool picture, uint curve) {
  vec3 c = max(linear, vec3(0.0));
  if (picture) c = srgb_encode(clamp(tone_curve(c, curve), 0.0, 1.0));
  uvec3 q = uvec3(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return q.r | (q.g << 8) | (q.b << 16) | (255u << 24);
}

#endif
