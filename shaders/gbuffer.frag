#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(std430, set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 1, binding = 0) uniform sampler2D base_color_texture;  // read when TEXTURED
layout(constant_id = 0) const bool DOUBLE_SIDED = false;  // back faces drawn (else culled)
layout(constant_id = 1) const bool TEXTURED = false;
layout(push_constant) uniform Draw { uint material; } draw;

layout(location = 0) out vec4 out_position;  // xyz: world position, w: material index + 1 (0 = nothing)
layout(location = 1) out vec4 out_normal;    // xyz: unit world normal
layout(location = 2) out vec4 out_albedo;    // rgb: linear albedo

void main() {
  vec3 n = normalize(in_normal);
  if (DOUBLE_SIDED && !gl_FrontFacing) n = -n;
  vec3 albedo = materials[draw.material].base_color.rgb;
  if (TEXTURED) albedo *= texture(base_color_texture, in_uv).rgb;
  out_position = vec4(in_world, float(draw.material + 1u));
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(albedo, 1.0);
}
