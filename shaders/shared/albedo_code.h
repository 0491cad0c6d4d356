// An 8-bit RGB albedo as one exactly representable integer in a float, the way surfels carry
// their albedo to the geometry volume: the RSM's normal texels (rsm.frag) and the scene's
// blockers (renderer/lpv/blocker_surfels.cpp) encode it here, lpv_geometry_inject.comp and
// lpv_gather_bounce.comp decode it. C++ compiles it as namespace gpu on glm; GLSL includes it
// as it is.
#ifndef LPV_ALBEDO_CODE_H
#define LPV_ALBEDO_CODE_H

#ifdef __cplusplus
#include <glm/glm.hpp>

namespace gpu {
using glm::clamp;
using glm::round;
using glm::uvec3;
using glm::vec3;
#define LPV_ALBEDO_FUNC inline
#else
#define LPV_ALBEDO_FUNC
#endif

LPV_ALBEDO_FUNC float albedo_code(vec3 albedo) {
  uvec3 q = uvec3(round(clamp(albedo, 0.0f, 1.0f) * 255.0f));
  return float(q.r | (q.g << 8) | (q.b << 16));
}

#ifndef __cplusplus
// The albedo back from its code (the shaders that read surfels).
vec3 albedo_decode(float code) {
  uint q = uint(code);
  return vec3(q & 255u, (q >> 8) & 255u, (q >> 16) & 255u) / 255.0;
}
#endif

#ifdef __cplusplus
}  // namespace gpu
#endif

#undef LPV_ALBEDO_FUNC
#endif
