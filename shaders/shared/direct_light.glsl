// Direct light from the frame's punctual lights with their shadow maps, shared by the
// deferred shading (shade.comp) and the forward pass (forward.frag) so both light alike.
// The includer declares before the include:
//   LIGHT_KINDS (uint)     the LIGHTS_* bits of the frame's lights and materials,
//   LIGHT_COUNT (uint)     the number of lights, or SHADE_LIGHTS_FROM_FRAME to read
//                          frame.size_view.w (both specialization constants: lavapipe runs
//                          both sides of a branch, so code for what the frame lacks costs
//                          every pixel, and a loop of constant length is unrolled),
//   frame (GpuFrame), lights[] (GpuLight), shadow_view_proj[] (mat4 per atlas layer) and
//   shadow_maps (sampler2DArrayShadow).
#ifndef LPV_DIRECT_LIGHT_GLSL
#define LPV_DIRECT_LIGHT_GLSL

const bool ANY_DIRECTIONAL = (LIGHT_KINDS & LIGHTS_DIRECTIONAL) != 0u;
const bool ANY_POSITIONAL = (LIGHT_KINDS & LIGHTS_POSITIONAL) != 0u;
const bool ANY_SHADOWED = (LIGHT_KINDS & LIGHTS_SHADOWED) != 0u;
const bool ANY_CUBE_SHADOWED = (LIGHT_KINDS & LIGHTS_CUBE_SHADOWED) != 0u;
const bool ANY_EMISSIVE = (LIGHT_KINDS & LIGHTS_EMISSIVE) != 0u;
#define LIGHTS_MAY_HAVE_CONE ((LIGHT_KINDS & LIGHTS_SPOT_CONE) != 0u)
#define LIGHTS_MAY_HAVE_RANGE ((LIGHT_KINDS & LIGHTS_RANGE) != 0u)
#include "lights.glsl"

// The cube face a direction falls in, in the order +X, -X, +Y, -Y, +Z, -Z.
uint cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x < 0.0 ? 1u : 0u;
  if (a.y >= a.z) return d.y < 0.0 ? 3u : 2u;
  return d.z < 0.0 ? 5u : 4u;
}

// Fraction of the light reaching p (1 = lit), with 2x2 PCF: the four depth comparisons of
// a compare gather, weighted bilinearly here. The same result as a filtered compare lookup
// (3e-8 apart on cornell-box when this was changed), which lavapipe runs a millisecond slower
// per 512^2 frame. The lookup point is pushed along the normal by about a shadow texel to
// keep surfaces from shadowing themselves.
float visibility(GpuLight light, vec3 p, vec3 n, float distance_to_light) {
  if (!ANY_SHADOWED || light.info.z == 0u) return 1.0;
  float offset = light.params.z * (light.info.x == LIGHT_DIRECTIONAL ? 1.0 : distance_to_light);
  vec3 q = p + n * offset;
  uint layer = light.info.y;
  if (ANY_CUBE_SHADOWED && light.info.z == 6u) layer += cube_face(q - light.position.xyz);  // a cube of six maps
  vec4 clip = shadow_view_proj[layer] * vec4(q, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  // Outside the map: nothing was rendered there that could occlude.
  if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0 || ndc.z < 0.0) return 1.0;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  vec2 t = uv * vec2(textureSize(shadow_maps, 0).xy) - 0.5;
  vec2 f = fract(t);
  vec4 lit = textureGather(shadow_maps, vec3(uv, float(layer)), ndc.z);  // texels (0,1), (1,1), (1,0), (0,0)
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// Irradiance (W/m^2) at p with unit normal n from one light, shadows included.
vec3 irradiance(GpuLight light, vec3 p, vec3 n) {
  if (ANY_DIRECTIONAL && (!ANY_POSITIONAL || light.info.x == LIGHT_DIRECTIONAL)) {
    vec3 to_light = -light.direction.xyz;
    float cos_theta = dot(n, to_light);
    if (cos_theta <= 0.0) return vec3(0.0);
    return light.radiant.rgb * cos_theta * visibility(light, p, n, 0.0);
  }
  vec3 to_light;
  float dist2;
  vec3 intensity = light_intensity_toward(light, p, to_light, dist2);
  float cos_theta = dot(n, to_light);
  if (cos_theta <= 0.0 || dist2 == 0.0 || intensity == vec3(0.0)) return vec3(0.0);
  return intensity * (cos_theta / dist2) * visibility(light, p, n, sqrt(dist2));
}

// Irradiance (W/m^2) at p with unit normal n from all the frame's lights, shadows included.
vec3 direct_irradiance(vec3 p, vec3 n) {
  vec3 e = vec3(0.0);
  for (uint i = 0u; i < (LIGHT_COUNT == SHADE_LIGHTS_FROM_FRAME ? frame.size_view.w : LIGHT_COUNT); ++i)
    e += irradiance(lights[i], p, n);
  return e;
}

#endif
