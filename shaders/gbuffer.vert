#version 450
// G-buffer: world-space position, normal and material of the closest surface per pixel.
#extension GL_GOOGLE_include_directive : require
#include "shared/camera_raster_interface.h"
#include "shared/gpu_types.h"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(std140, set = 0, binding = CAMERA_FRAME) uniform Frame { GpuFrame frame; };

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_uv;

void main() {
  out_world = in_position;
  out_normal = in_normal;
  out_uv = in_uv;
  gl_Position = frame.view_proj * vec4(in_position, 1.0);
}
