#version 450
// Reflective shadow maps: the scene from one light view (see rsm.frag).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/rsm_interface.h"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(std140, set = 0, binding = RSM_VIEWS) uniform Views { GpuRsmView views[SHADE_MAX_SHADOW_VIEWS]; };
layout(push_constant) uniform Draw { GpuDrawMaterial material; uint view; } draw;

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_uv;

void main() {
  out_world = in_position;
  out_normal = in_normal;
  out_uv = in_uv;
  gl_Position = views[draw.view].view_proj * vec4(in_position, 1.0);
}
