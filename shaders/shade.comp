#version 450
// Direct lighting of the G-buffer: Lambertian surfaces lit by punctual lights with
// shadow maps. Output: one linear RGBA float per pixel (radiance * 2^exposure for the
// lit views, the raw quantity for the data views).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"

layout(local_size_x = SHADE_GROUP_X, local_size_y = SHADE_GROUP_Y) in;

layout(std140, set = 0, binding = 0) uniform Frame { GpuFrame frame; };
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D g_position;
layout(set = 0, binding = 2, rgba16f) uniform readonly image2D g_normal;
layout(set = 0, binding = 3, rgba16f) uniform readonly image2D g_albedo;
layout(set = 0, binding = 4) uniform sampler2DArrayShadow shadow_maps;
layout(std430, set = 0, binding = 5) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = 6) readonly buffer ShadowViews { mat4 shadow_view_proj[]; };
layout(std430, set = 0, binding = 7) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Image { vec4 pixels[]; };

const float PI = 3.14159265358979;

// The cube face a direction falls in, in the order +X, -X, +Y, -Y, +Z, -Z.
uint cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x < 0.0 ? 1u : 0u;
  if (a.y >= a.z) return d.y < 0.0 ? 3u : 2u;
  return d.z < 0.0 ? 5u : 4u;
}

// Fraction of the light reaching p (1 = lit), with 2x2 hardware PCF. The lookup point is
// pushed along the normal by about a shadow texel to keep surfaces from shadowing themselves.
float visibility(GpuLight light, vec3 p, vec3 n, float distance_to_light) {
  if (light.info.z == 0u) return 1.0;
  float offset = light.params.z * (light.info.x == LIGHT_DIRECTIONAL ? 1.0 : distance_to_light);
  vec3 q = p + n * offset;
  uint layer = light.info.y;
  if (light.info.z == 6u) layer += cube_face(q - light.position.xyz);  // a cube of six maps
  vec4 clip = shadow_view_proj[layer] * vec4(q, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  // Outside the map: nothing was rendered there that could occlude.
  if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0 || ndc.z < 0.0) return 1.0;
  return texture(shadow_maps, vec4(ndc.xy * 0.5 + 0.5, float(layer), ndc.z));
}

// Irradiance (W/m^2) at p with unit normal n from one light, shadows included.
vec3 irradiance(GpuLight light, vec3 p, vec3 n) {
  if (light.info.x == LIGHT_DIRECTIONAL) {
    vec3 to_light = -light.direction.xyz;
    float cos_theta = dot(n, to_light);
    if (cos_theta <= 0.0) return vec3(0.0);
    return light.radiant.rgb * cos_theta * visibility(light, p, n, 0.0);
  }
  vec3 d = light.position.xyz - p;
  float dist2 = dot(d, d);
  float dist = sqrt(dist2);
  vec3 to_light = d / dist;
  float cos_theta = dot(n, to_light);
  if (cos_theta <= 0.0 || dist2 == 0.0) return vec3(0.0);
  float attenuation = 1.0 / dist2;
  float range = light.direction.w;
  if (range > 0.0) {
    float r = dist / range;  // glTF KHR_lights_punctual recommended window
    attenuation *= clamp(1.0 - r * r * r * r, 0.0, 1.0);
  }
  if (light.info.x == LIGHT_SPOT) {
    float cd = dot(light.direction.xyz, -to_light);
    float a = clamp(cd * light.params.x + light.params.y, 0.0, 1.0);
    attenuation *= a * a;
  }
  if (attenuation == 0.0) return vec3(0.0);
  return light.radiant.rgb * (cos_theta * attenuation) * visibility(light, p, n, dist);
}

void main() {
  uvec2 size = frame.size_view.xy;
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  uint index = pixel.y * size.x + pixel.x;

  vec4 position = imageLoad(g_position, ivec2(pixel));
  if (position.w == 0.0) {  // no surface: black background
    pixels[index] = vec4(0.0);
    return;
  }
  vec3 p = position.xyz;
  vec3 n = normalize(imageLoad(g_normal, ivec2(pixel)).xyz);
  vec3 albedo = imageLoad(g_albedo, ivec2(pixel)).rgb;
  uint material = uint(position.w) - 1u;

  uint view = frame.size_view.z;
  vec3 value;
  if (view == VIEW_ALBEDO) {
    value = albedo;
  } else if (view == VIEW_NORMAL) {
    value = n * 0.5 + 0.5;
  } else if (view == VIEW_DEPTH) {
    float depth = dot(p - frame.camera_position.xyz, frame.camera_forward.xyz);
    value = vec3(clamp((depth - frame.depth_range.x) / (frame.depth_range.y - frame.depth_range.x), 0.0, 1.0));
  } else {
    vec3 e = vec3(0.0);
    for (uint i = 0u; i < frame.size_view.w; ++i) e += irradiance(lights[i], p, n);
    value = (albedo / PI * e + materials[material].emissive.rgb) * frame.exposure.x;
  }
  pixels[index] = vec4(value, 1.0);
}
