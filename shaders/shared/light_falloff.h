// How a punctual light falls off (KHR_lights_punctual), shared by C++ and GLSL so the shading
// and the RSMs (lights.glsl), the light setup (renderer/frame_setup.cpp) and the path-traced
// reference (reference/punctual_lights.cpp) use one definition: the spot cone's
// smooth edge and the range window. C++ compiles the functions as templates on the scalar
// (the reference computes in double), GLSL in float.
#ifndef LPV_LIGHT_FALLOFF_H
#define LPV_LIGHT_FALLOFF_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace gpu {
#define LPV_FALLOFF_FUNC(T) template <typename T> inline T
template <typename T>
inline T saturate(T v) {
  return std::clamp(v, T(0), T(1));
}
#else
#define LPV_FALLOFF_FUNC(T) float
#define real float
float saturate(float v) { return clamp(v, 0.0, 1.0); }
#endif

// The glTF range window at `distance` from a light of range `range` > 0: clamp(1 - (d/r)^4, 0, 1).
LPV_FALLOFF_FUNC(real) range_window(real distance, real range) {
  const real r = distance / range;
  return saturate(real(1) - r * r * r * r);
}

// A spot's falloff towards a direction at `cos_angle` to its axis: the square of the glTF
// cone ramp clamp(cos_angle * scale + offset, 0, 1) (spot_cone_constants).
LPV_FALLOFF_FUNC(real) spot_cone(real cos_angle, real scale, real offset) {
  const real a = saturate(cos_angle * scale + offset);
  return a * a;
}

#ifdef __cplusplus
// The ramp's scale and offset for a cone from inner_deg (full light) to outer_deg (none), in
// float as the GPU reads them: 1 at the inner cone, 0 at the outer.
inline glm::vec2 spot_cone_constants(float inner_deg, float outer_deg) {
  const float cos_outer = std::cos(glm::radians(outer_deg));
  const float cos_inner = std::cos(glm::radians(inner_deg));
  const float scale = 1.0f / std::max(1e-3f, cos_inner - cos_outer);
  return {scale, -cos_outer * scale};
}

}  // namespace gpu
#else
#undef real
#endif

#undef LPV_FALLOFF_FUNC
#endif
