#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(std430, set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 1, binding = 0) uniform sampler2D base_color_texture;  // white when untextured
layout(push_constant) uniform Draw { uint material; } draw;

layout(location = 0) out vec4 out_position;  // xyz: world position, w: material index + 1 (0 = nothing)
layout(location = 1) out vec4 out_normal;    // xyz: unit world normal
layout(location = 2) out vec4 out_albedo;    // rgb: linear albedo

void main() {
  GpuMaterial material = materials[draw.material];
  vec3 n = normalize(in_normal);
  if (!gl_FrontFacing) {
    if (material.flags.x == 0u) discard;  // one-sided: seen from behind, not there
    n = -n;
  }
  out_position = vec4(in_world, float(draw.material + 1u));
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(material.base_color.rgb * texture(base_color_texture, in_uv).rgb, 1.0);
}
