// Punctual lights in the units of KHR_lights_punctual (DESIGN.md section 2), shared by the
// direct shading and the reflective shadow maps so both see the same light.
#ifndef LPV_LIGHTS_GLSL
#define LPV_LIGHTS_GLSL

#include "light_falloff.h"

// An includer that knows no light has a spot cone or a range window may define these false
// (lavapipe runs both sides of a branch, so code that cannot apply still costs).
#ifndef LIGHTS_MAY_HAVE_CONE
#define LIGHTS_MAY_HAVE_CONE true
#endif
#ifndef LIGHTS_MAY_HAVE_RANGE
#define LIGHTS_MAY_HAVE_RANGE true
#endif

// Radiant intensity (W/sr) a point or spot light sends toward p, with the spot's smooth cone
// and the glTF range window; `to_light` (unit) and `dist2` describe the path from p.
vec3 light_intensity_toward(GpuLight light, vec3 p, out vec3 to_light, out float dist2) {
  vec3 d = light.position.xyz - p;
  dist2 = dot(d, d);
  to_light = dist2 > 0.0 ? d * inversesqrt(dist2) : vec3(0.0);
  float attenuation = 1.0;
  float range = light.direction.w;
  if (LIGHTS_MAY_HAVE_RANGE && range > 0.0) attenuation = range_window(sqrt(dist2), range);
  if (LIGHTS_MAY_HAVE_CONE && light.info.x == LIGHT_SPOT)
    attenuation *= spot_cone(dot(light.direction.xyz, -to_light), light.params.x, light.params.y);
  return light.radiant.rgb * attenuation;
}

#endif
