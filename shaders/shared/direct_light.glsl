// Direct light from the frame's punctual lights with their shadow maps, shared by the
// deferred shading (shade.comp) and the forward pass (forward.frag) so both light alike.
// The includer declares before the include:
//   LIGHT_KINDS (uint)     the LIGHTS_* bits of the frame's lights and materials,
//   LIGHT_COUNT (uint)     the number of lights, or SHADE_LIGHTS_FROM_FRAME to read
//                          frame.size_view.w (both specialization constants: lavapipe runs
//                          both sides of a branch, so code for what the frame lacks costs
//                          every pixel, and a loop of constant length is unrolled),
//   frame (GpuFrame), lights[] (GpuLight), shadow_views[] (GpuShadowView per atlas layer) and
//   shadow_maps (sampler2DArray: the maps' depths, nearest texels).
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

// The shadow lookup's distances, in shadow texels at the receiver (GpuLight::params.z).
const float SHADOW_RECEIVER_REACH = 1.5;  // how far behind p the receiver's plane is followed
const float SHADOW_NORMAL_ERROR = 2e-3;   // the receiver's plane's error over the four texels, per texel
const float SHADOW_SNAP = 1.0 / 64.0;      // the rasteriser's vertex snapping, in texels, with a margin

// Fraction of the light reaching p (1 = lit): 2x2 PCF, the four texels around p weighted
// bilinearly, each compared with the depth of the receiver's own plane (through p, normal n)
// at that texel's centre: "receiver plane depth" (a plane's depth in a map is affine in the
// map's x and y, perspective maps included).
//
// Why per texel: comparing the four with one depth let light through seams. An occluder seen
// at a grazing angle (a ceiling, under a low sun) changes depth across a texel by more than it
// stands in front of a receiver that meets it (the wall under the ceiling), so the texels on
// its far side counted the wall lit, a line of full sunlight along the seam. A slope bias on
// the occluders and a lookup pushed 1.5 texels along the normal, which kept a single depth off
// the receiver's own surface before, widened that line, and the push moved shadows' edges
// sideways on surfaces the light grazes (by 1.5 texels over the cosine, a few pixels). The
// receiver's own surface needs neither: its texels hold its own plane.
//
// The plane is followed at most SHADOW_RECEIVER_REACH texels behind p along the light: a
// surface nearly edge-on to the light reaches far in depth within a texel, past where it ends
// (under the floor it stands on), where whatever the texel holds would shadow it.
//
// A texel where nothing was drawn (still at the clear depth, 1) holds no receiver: a lookup
// reaches it only past the edge of all the light sees. Past an occluder's edge that meets a
// receiver (nothing beyond the roof), counting it lit would leak; it counts as the drawn
// texels of the four do: lit only where all of them are. A surface's own edge (a plane that
// ends in nothing) stays lit.
float visibility(GpuLight light, vec3 p, vec3 n, vec3 to_light, float distance_to_light) {
  if (!ANY_SHADOWED || light.info.z == 0u) return 1.0;
  float texel_size = light.params.z * (light.info.x == LIGHT_DIRECTIONAL ? 1.0 : distance_to_light);
  uint layer = light.info.y;
  if (ANY_CUBE_SHADOWED && light.info.z == 6u) layer += cube_face(p - light.position.xyz);  // a cube of six maps
  GpuShadowView view = shadow_views[layer];
  vec4 clip = view.view_proj * vec4(p, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  // Outside the map: nothing was rendered there that could occlude.
  if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0 || ndc.z < 0.0) return 1.0;

  // The receiver's plane in clip space, P: a point of it has <P, (x, y, depth, 1)> = 0 in
  // normalized device coordinates, so its depth at map position s is
  // ndc.z - <P.xy, s - ndc.xy> / P.z.
  vec4 plane = view.plane_to_clip * vec4(n, -dot(n, p));
  if (!(abs(plane.z) > 0.0)) return 1.0;  // edge-on to the light, which it then only grazes: n.l ~ 0
  vec2 slope = -plane.xy / plane.z;
  vec4 behind = view.view_proj * vec4(p - to_light * (SHADOW_RECEIVER_REACH * texel_size), 1.0);
  float deepest = behind.z / behind.w;

  vec2 size = vec2(textureSize(shadow_maps, 0).xy);
  vec2 t = (ndc.xy * 0.5 + 0.5) * size - 0.5;
  vec2 f = fract(t);
  vec2 texel = 2.0 / size;                     // a texel, in map x, y
  vec2 first = (floor(t) + 0.5) * texel - 1.0; // texel (0,0)'s centre
  float depth_00 = ndc.z + dot(slope, first - ndc.xy);
  vec4 receiver = depth_00 + vec4(slope.y * texel.y, dot(slope, texel), slope.x * texel.x, 0.0);
  // Leeway against the receiver's own texels, in texels along the light. The plane's slope is
  // as good as the normal, rounded to 16 bits in the G-buffer (5e-4): across a texel and a half
  // that moves its depth by the normal's error times 1 + tan^2 of the light's angle to it. And
  // the map's rasteriser snaps vertices to a fraction of a texel (1/256 on NVIDIA's), which
  // moves a surface's stored depth by that fraction times tan. A receiver the light grazes needs
  // both; one it faces (a wall under a ceiling) next to none.
  float texel_depth = (deepest - ndc.z) / SHADOW_RECEIVER_REACH;
  float tangent = length(slope * texel) / texel_depth;
  float leeway = SHADOW_NORMAL_ERROR * (1.0 + tangent * tangent) + SHADOW_SNAP * tangent;
  receiver = min(receiver, vec4(deepest)) - (1e-6 + leeway * texel_depth);
  vec4 stored = textureGather(shadow_maps, vec3(ndc.xy * 0.5 + 0.5, float(layer)), 0);  // texels (0,1), (1,1), (1,0), (0,0)
  vec4 lit = vec4(lessThanEqual(receiver, stored));
  vec4 empty = vec4(greaterThanEqual(stored, vec4(1.0)));
  vec4 drawn = max(lit, empty);  // the empty ones left out of the least
  lit = mix(lit, vec4(min(min(drawn.x, drawn.y), min(drawn.z, drawn.w))), empty);
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// Irradiance (W/m^2) at p with unit normal n from one light, shadows included.
vec3 irradiance(GpuLight light, vec3 p, vec3 n) {
  if (ANY_DIRECTIONAL && (!ANY_POSITIONAL || light.info.x == LIGHT_DIRECTIONAL)) {
    vec3 to_light = -light.direction.xyz;
    float cos_theta = dot(n, to_light);
    if (cos_theta <= 0.0) return vec3(0.0);
    return light.radiant.rgb * cos_theta * visibility(light, p, n, to_light, 0.0);
  }
  vec3 to_light;
  float dist2;
  vec3 intensity = light_intensity_toward(light, p, to_light, dist2);
  float cos_theta = dot(n, to_light);
  if (cos_theta <= 0.0 || dist2 == 0.0 || intensity == vec3(0.0)) return vec3(0.0);
  return intensity * (cos_theta / dist2) * visibility(light, p, n, to_light, sqrt(dist2));
}

// Irradiance (W/m^2) at p with unit normal n from all the frame's lights, shadows included.
vec3 direct_irradiance(vec3 p, vec3 n) {
  vec3 e = vec3(0.0);
  for (uint i = 0u; i < (LIGHT_COUNT == SHADE_LIGHTS_FROM_FRAME ? frame.size_view.w : LIGHT_COUNT); ++i)
    e += irradiance(lights[i], p, n);
  return e;
}

#endif
