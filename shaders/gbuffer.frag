#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/material_surface.glsl"

layout(location = 0) out vec4 out_position;  // xyz: world position, w: material index + 1 (0 = nothing)
layout(location = 1) out vec4 out_normal;    // xyz: unit world normal
layout(location = 2) out vec4 out_albedo;    // rgb: linear albedo

void main() {
  vec3 n, albedo;
  material_surface(n, albedo);
  out_position = vec4(in_world, float(draw.index.x + 1u));
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(albedo, 1.0);
}
