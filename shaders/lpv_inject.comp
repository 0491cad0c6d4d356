#version 450
// Injection: every RSM texel (or block of vpl_downsample^2 texels merged into one brighter VPL)
// is a virtual point light (shared/lpv_inject_vpl.glsl).
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_inject_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"

layout(local_size_x = LPV_VPL_GROUP, local_size_y = LPV_VPL_GROUP) in;

layout(std140, set = 0, binding = INJECT_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = INJECT_RSM_POSITION, rgba32f) uniform readonly image2DArray rsm_position;
layout(set = 0, binding = INJECT_RSM_NORMAL, rgba32f) uniform readonly image2DArray rsm_normal;
layout(set = 0, binding = INJECT_RSM_FLUX, rgba32f) uniform readonly image2DArray rsm_flux;
layout(std430, set = 0, binding = INJECT_INJECTED) buffer Injected { int64_t injected[]; };  // 12 per cell: RGB x SH
layout(std430, set = 0, binding = INJECT_FLUX_STATS) buffer FluxStats { int64_t flux_stats[]; };
layout(push_constant) uniform Push { LpvInjectPush push; };

#include "shared/lpv_grid_flux.glsl"
#include "shared/lpv_inject_vpl.glsl"

void main() {
  uint block = lpv.sizes.y;
  uint vpls_per_side = lpv.sizes.x / block;
  uvec3 id = splat_group_point();
  bool in_range = id.x < vpls_per_side && id.y < vpls_per_side;

  // Merge the block: flux adds up; position and normal are flux-weighted means.
  vec3 flux = vec3(0.0);
  vec3 position = vec3(0.0);
  vec3 normal = vec3(0.0);
  for (uint y = 0u; in_range && y < block; ++y) {
    for (uint x = 0u; x < block; ++x) {
      ivec3 texel = ivec3(id.xy * block + uvec2(x, y), id.z);
      if (imageLoad(rsm_position, texel).w == 0.0) continue;
      vec3 f = imageLoad(rsm_flux, texel).rgb;
      float w = f.r + f.g + f.b;
      flux += f;
      position += w * imageLoad(rsm_position, texel).xyz;
      normal += w * imageLoad(rsm_normal, texel).xyz;
    }
  }
  float weight = flux.r + flux.g + flux.b;

  // The flux of all VPLs, for the statistics.
  add_grid_flux(flux, push.stats_record, lpv.scales.x);

  bool lit = weight > 0.0 && dot(normal, normal) > 0.0;
  ivec3 low;
  vec3 f;
  float values[SPLAT_VALUES];
  bool inside = vpl_splat(lit ? position / weight : vec3(0.0), lit ? normalize(normal) : vec3(0.0, 0.0, 1.0), flux, low, f, values);
  splat_subgroup(lit && inside, low, f, values, vpl_last_cell(), lpv.scales.x);
}
