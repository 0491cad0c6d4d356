#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(std430, set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };
layout(push_constant) uniform Draw { uint material; } draw;

layout(location = 0) out vec4 out_position;  // xyz: world position, w: material index + 1 (0 = nothing)
layout(location = 1) out vec4 out_normal;    // xyz: unit world normal
layout(location = 2) out vec4 out_albedo;    // rgb: linear albedo

void main() {
  out_position = vec4(in_world, float(draw.material + 1u));
  out_normal = vec4(normalize(in_normal), 0.0);
  out_albedo = vec4(materials[draw.material].base_color.rgb, 1.0);
}
