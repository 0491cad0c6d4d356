// Linear value -> one 8-bit RGBA pixel for display: optional tone curve, clamp, sRGB transfer.
// Data views (normal, depth) are quantised linearly instead. renderer/accuracy/display_image.cpp
// is the CPU's copy, for images no render produced; the two must agree to one level.
#ifndef LPV_DISPLAY_ENCODE_GLSL
#define LPV_DISPLAY_ENCODE_GLSL

vec3 tone_curve(vec3 x, uint curve) {
  if (curve == TONEMAP_REINHARD) return x / (1.0 + x);
  if (curve == TONEMAP_ACES) return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);  // Narkowicz fit
  return x;
}

vec3 srgb_encode(vec3 c) {
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

// `picture`: tone curve and sRGB; else the value is data, quantised linearly. Negative and NaN
// components are black.
uint display_pixel(vec3 linear, bool picture, uint curve) {
  vec3 c = max(linear, vec3(0.0));
  if (picture) c = srgb_encode(clamp(tone_curve(c, curve), 0.0, 1.0));
  uvec3 q = uvec3(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return q.r | (q.g << 8) | (q.b << 16) | (255u << 24);
}

#endif
