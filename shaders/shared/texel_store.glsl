// Writing (and reading back) texel buffers (vkx::TexelBuffer) through their storage-buffer
// view. The view is declared as u64vec2 per 16-byte texel and a texel is stored as two 64-bit
// halves:
// lavapipe scatters a storage-buffer store one lane at a time, checking every component
// against the buffer's end, so two 64-bit components cost about half of four 32-bit ones
// (propagation 10% faster in one-off alternated runs, commit ff83845).
#ifndef LPV_TEXEL_STORE_GLSL
#define LPV_TEXEL_STORE_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

u64vec2 texel_bits(vec4 v) {
  uvec4 u = floatBitsToUint(v);
  return u64vec2(packUint2x32(u.xy), packUint2x32(u.zw));
}

// A texel stored so, read back through the same view.
vec4 texel_value(u64vec2 bits) { return uintBitsToFloat(uvec4(unpackUint2x32(bits.x), unpackUint2x32(bits.y))); }

#endif
