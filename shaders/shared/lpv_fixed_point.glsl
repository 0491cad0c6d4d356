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

#endif
