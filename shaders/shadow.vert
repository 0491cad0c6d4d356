#version 450
// Depth-only rendering of the scene from a light: one shadow map layer per call.
layout(location = 0) in vec3 in_position;
layout(push_constant) uniform View { mat4 view_proj; } view;

void main() { gl_Position = view.view_proj * vec4(in_position, 1.0); }
