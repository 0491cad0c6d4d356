#version 450
// One reflective shadow map texel: the surfel the light sees first, as a virtual point light.
// Its flux is albedo times the flux reaching the surfel (DESIGN.md section 2): I * (texel solid
// angle) for a spot or point light, E * (texel area) for a directional light. The texel already
// measures projected area, so no cosine of the surface enters.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/rsm_interface.h"
#include "shared/lights.glsl"
#include "shared/albedo_code.h"
#include "shared/material_texture_interface.h"

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;

// Uniform buffers and the draw's material as push constants, not storage buffers: lavapipe
// loads a fragment shader's storage buffer lane by lane even at an address all lanes share
// (as in forward.frag). The buffers are sized for the most views and lights a frame may have.
layout(std140, set = 0, binding = RSM_VIEWS) uniform Views { GpuRsmView views[SHADE_MAX_SHADOW_VIEWS]; };
layout(std140, set = 0, binding = RSM_LIGHTS) uniform Lights { GpuLight lights[SHADE_MAX_LIGHTS]; };
layout(set = MATERIAL_TEXTURE_SET, binding = MATERIAL_BASE_COLOR) uniform sampler2D base_color_texture;
layout(constant_id = 0) const bool TEXTURED = false;
layout(push_constant) uniform Draw { GpuDrawMaterial material; uint view; } draw;

layout(location = 0) out vec4 out_position;  // xyz: world position; w: 1 (0 = nothing seen)
layout(location = 1) out vec4 out_normal;    // xyz: unit normal; w: albedo as 8-bit RGB code
layout(location = 2) out vec4 out_flux;      // rgb: reflected flux (W); w: surfel area (m^2)

// Surfaces seen edge-on from the light get at most this many times their projected area.
const float MIN_AREA_COSINE = 0.25;

void main() {
  GpuRsmView view = views[draw.view];
  GpuLight light = lights[view.info.x];
  GpuMaterial material = draw.material.material;
  vec3 n = normalize(in_normal);
  vec3 albedo = material.base_color.rgb;
  if (TEXTURED) albedo *= texture(base_color_texture, in_uv).rgb;
  float texel = view.axis.w;  // texel side: at unit distance (perspective) or in metres

  vec3 to_light;
  vec3 incident;            // flux reaching the surfel (W)
  float projected_area;     // of the surfel, perpendicular to the light's rays (m^2)
  if (view.info.y == RSM_VIEW_ORTHOGRAPHIC) {
    to_light = -light.direction.xyz;
    projected_area = texel * texel;
    incident = light.radiant.rgb * projected_area;
  } else {
    float dist2;
    vec3 intensity = light_intensity_toward(light, in_world, to_light, dist2);
    float cos_axis = max(dot(-to_light, view.axis.xyz), 0.0);
    float solid_angle = texel * texel * cos_axis * cos_axis * cos_axis;
    projected_area = solid_angle * dist2;
    incident = intensity * solid_angle;
  }
  if (material.flags.x != 0u && dot(n, to_light) < 0.0) n = -n;  // double-sided: the lit side reflects
  float cos_surface = dot(n, to_light);
  out_position = vec4(in_world, 1.0);
  out_normal = vec4(n, albedo_code(albedo));
  out_flux = vec4(cos_surface > 0.0 ? albedo * incident : vec3(0.0),
                  projected_area / max(abs(cos_surface), MIN_AREA_COSINE));
}
