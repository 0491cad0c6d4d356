// Deterministic accumulation: the LPV passes that scatter (injection, geometry volume, flux
// statistics) add 64-bit fixed-point integers with atomics. Integer addition is associative,
// so the result does not depend on the order threads run in: identical requests give bitwise
// identical grids. Float atomics would not.
#ifndef LPV_FIXED_POINT_GLSL
#define LPV_FIXED_POINT_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

int64_t to_fixed(float x, float units_per_one) { return int64_t(round(x * units_per_one)); }
float from_fixed(int64_t x, float one_per_unit) { return float(x) * one_per_unit; }
vec4 from_fixed(i64vec2 xy, i64vec2 zw, float one_per_unit) {
  return vec4(float(xy.x), float(xy.y), float(zw.x), float(zw.y)) * one_per_unit;
}

// The two sums of a texel of a buffer of them read as RGBA32UI (lavapipe gathers texels with
// vector loads, where it reads a storage buffer one lane at a time): little-endian halves.
i64vec2 fixed_pair(uvec4 texel) {
  return i64vec2(int64_t(uint64_t(texel.x) | (uint64_t(texel.y) << 32)),
                 int64_t(uint64_t(texel.z) | (uint64_t(texel.w) << 32)));
}

#endif
