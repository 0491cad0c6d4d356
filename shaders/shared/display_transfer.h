// The display transfer, shared by C++ and GLSL so the shading (display_encode.glsl), the CPU's
// pictures of linear images (lab/accuracy/display_image.cpp) and the textures' mip chains
// (scene/texture_mips.cpp) use one definition: the tone curves and the sRGB curve
// (IEC 61966-2-1) both ways. C++ compiles it as namespace gpu on glm; GLSL includes it after
// gpu_types.h.
#ifndef LPV_DISPLAY_TRANSFER_H
#define LPV_DISPLAY_TRANSFER_H

#ifdef __cplusplus
#include "shaders/shared/gpu_types.h"

#include <glm/glm.hpp>

#include <cmath>

namespace gpu {
using glm::vec3;
using glm::bvec3;
using glm::greaterThan;
using glm::mix;
using glm::pow;
#define LPV_DISPLAY_FUNC inline
#else
#define LPV_DISPLAY_FUNC
#endif

// The tone curve TONEMAP_* of linear light x >= 0 (TONEMAP_NONE: x itself).
LPV_DISPLAY_FUNC vec3 tone_curve(vec3 x, uint curve) {
  if (curve == TONEMAP_REINHARD) return x / (1.0f + x);
  if (curve == TONEMAP_ACES) return (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);  // Narkowicz fit
  return x;
}

// Linear light in [0, 1] to its sRGB encoding.
LPV_DISPLAY_FUNC vec3 srgb_encode(vec3 c) {
  return mix(12.92f * c, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, greaterThan(c, vec3(0.0031308f)));
}

#ifdef __cplusplus
// An sRGB-encoded value in [0, 1] to linear light, in float or double (the sampler's decoding,
// which the GPU does for the textures).
template <typename Real>
Real srgb_decode(Real c) {
  return c <= Real(0.04045) ? c / Real(12.92) : std::pow((c + Real(0.055)) / Real(1.055), Real(2.4));
}

}  // namespace gpu
#endif

#undef LPV_DISPLAY_FUNC
#endif
