// The surface a raster pass of the camera sees at a fragment: its unit normal (flipped on the
// back of a double-sided material) and albedo (base colour times texture). Shared by the
// G-buffer (gbuffer.frag) and the forward pass (forward.frag), which both run behind
// gbuffer.vert. Declares its inputs, specialization constants 0 and 1, set 1 and the push
// constants (the draw's material: GpuDrawMaterial).
#ifndef LPV_MATERIAL_SURFACE_GLSL
#define LPV_MATERIAL_SURFACE_GLSL

#include "material_texture_interface.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

layout(set = MATERIAL_TEXTURE_SET, binding = MATERIAL_BASE_COLOR) uniform sampler2D base_color_texture;
layout(constant_id = 0) const bool DOUBLE_SIDED = false;  // back faces drawn (else culled)
layout(constant_id = 1) const bool TEXTURED = false;
layout(push_constant) uniform Draw { GpuDrawMaterial draw; };

void material_surface(out vec3 n, out vec3 albedo) {
  n = normalize(in_normal);
  if (DOUBLE_SIDED && !gl_FrontFacing) n = -n;
  albedo = draw.material.base_color.rgb;
  if (TEXTURED) albedo *= texture(base_color_texture, in_uv).rgb;
}

#endif
