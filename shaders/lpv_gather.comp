#version 450
// The gather transfer (lpv_gather.h, docs/lpv.md "The gather"): each cell of a slab of layers
// sums the light of every lit injected cell of its cascade, the near ones one by one and those
// further off in blocks (the pyramid lpv_gather_sources.comp builds), each from where its light
// left its surfaces, its line of sight from the cell its light was added around
// (lpv_gather_line_start) through the faces of the geometry volume, into its irradiance cube. The sums run over levels and blocks in a fixed
// order, so the result is deterministic.
#extension GL_GOOGLE_include_directive : require
#include "shared/gpu_types.h"
#include "shared/lpv_gather_interface.h"
#include "shared/lpv_sh.h"
#include "shared/lpv_gather.h"
#include "shared/lpv_grid.glsl"
#include "shared/lpv_fixed_point.glsl"
#include "shared/texel_store.glsl"

layout(local_size_x = LPV_GROUP, local_size_y = LPV_GROUP, local_size_z = LPV_GROUP) in;

layout(std140, set = 0, binding = GATHER_LPV) uniform Lpv { GpuLpv lpv; };
layout(set = 0, binding = GATHER_INJECTED, rgba32ui) uniform readonly uimageBuffer injected;  // 6 texels of 2 sums per cell
layout(set = 0, binding = GATHER_FACES, rgba32f) uniform readonly imageBuffer faces;          // lpv_face_texel
layout(set = 0, binding = GATHER_SOURCES, rgba32f) uniform readonly imageBuffer sources;      // lpv_gather_sources.comp's pyramid
layout(std430, set = 0, binding = GATHER_ACCUMULATED_STORE_R) buffer AccumulatedR { u64vec2 accumulated_r[]; };
layout(std430, set = 0, binding = GATHER_ACCUMULATED_STORE_G) buffer AccumulatedG { u64vec2 accumulated_g[]; };
layout(std430, set = 0, binding = GATHER_ACCUMULATED_STORE_B) buffer AccumulatedB { u64vec2 accumulated_b[]; };
layout(std430, set = 0, binding = GATHER_BOUNCE_STORE_R) writeonly buffer BounceR { u64vec2 bounce_r[]; };
layout(std430, set = 0, binding = GATHER_BOUNCE_STORE_G) writeonly buffer BounceG { u64vec2 bounce_g[]; };
layout(std430, set = 0, binding = GATHER_BOUNCE_STORE_B) writeonly buffer BounceB { u64vec2 bounce_b[]; };
layout(push_constant) uniform Push { LpvGatherPush push; };

// The geometry volume blocks the light (a frame with occlusion).
layout(constant_id = 0) const bool OCCLUDED = true;

// The fraction of light along w that gets from cell `from` to cell `to`: the faces the line
// between their centres crosses, in the order it crosses them (lpv_gather_next_axis).
float transmitted(ivec3 from, ivec3 to, vec3 w, uvec3 dims) {
  ivec3 d = to - from;
  ivec3 span = abs(d);
  ivec3 step = ivec3(sign(vec3(d)));
  ivec3 next = ivec3(1);  // each axis's next crossing, t = next / (2 span)
  int crossings = span.x + span.y + span.z;
  ivec3 cell = from;
  float through = 1.0;
  for (int i = 0; i < crossings && through > 0.0; ++i) {
    int axis = lpv_gather_next_axis(next, span);
    ivec3 ahead = cell;
    ahead[axis] += step[axis];
    ivec3 owner = step[axis] > 0 ? cell : ahead;  // a face is stored with the cell below it
    vec4 b = imageLoad(faces, lpv_face_texel(owner, axis, dims));
    vec3 spread = imageLoad(faces, lpv_face_spread_texel(owner, axis, dims)).xyz;
    vec3 face_centre = 0.5 * (vec3(cell) + vec3(ahead));
    through *= lpv_gather_transmitted(b, spread, w, vec3(from) - face_centre, vec3(to) - face_centre);
    cell = ahead;
    next[axis] += 2;
  }
  return max(through, 0.0);
}

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  uvec3 dims = g.dims.xyz;
  ivec3 cell = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, int(push.first_layer));
  if (any(greaterThanEqual(cell, ivec3(dims))) || cell.z >= int(push.first_layer + push.layers)) return;
  vec3 cube[6] = vec3[6](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
  bool last = false;
  for (int level = 0; !last; ++level) {
    LpvGatherWindow window = lpv_gather_window(cell, level, ivec3(dims));
    last = window.last;
    ivec3 level_dims = lpv_gather_level_dims(ivec3(dims), level);
    int first = lpv_gather_level_first(ivec3(dims), level);
    for (int z = window.lo.z; z <= window.hi.z; ++z)
      for (int y = window.lo.y; y <= window.hi.y; ++y)
        for (int x = window.lo.x; x <= window.hi.x; ++x) {
          ivec3 block = ivec3(x, y, z);
          if (lpv_gather_gathered_finer(block, cell, level)) continue;
          int record = LPV_GATHER_RECORD_TEXELS * (first + x + level_dims.x * (y + level_dims.y * z));
          vec3 flux_per_pi = imageLoad(sources, record + 1).xyz;
          if (!(flux_per_pi.x + flux_per_pi.y + flux_per_pi.z > 0.0)) continue;  // no light there
          if (level == 0 && block == cell) {
            // Its own light, whose VPLs lie within the cell: read from its SH.
            int here = int(lpv_cell_index(uvec3(cell), dims));
            vec4 sh[3];
            for (int c = 0; c < 3; ++c)
              sh[c] = from_fixed(fixed_pair(imageLoad(injected, 6 * here + 2 * c)),
                                 fixed_pair(imageLoad(injected, 6 * here + 2 * c + 1)), 1.0 / lpv.scales.x);
            for (int a = 0; a < 6; ++a)
              cube[a] += vec3(lpv_gather_own_cell(sh[0], a), lpv_gather_own_cell(sh[1], a), lpv_gather_own_cell(sh[2], a));
            continue;
          }
          vec4 emitter = lpv_gather_emitter(imageLoad(sources, record), lpv.transfer.y);
          vec3 centre = imageLoad(sources, record + 2).xyz;
          vec3 d = vec3(cell) - centre;
          float axes[6];
          float any_light = 0.0;
          for (int a = 0; a < 6; ++a) {
            axes[a] = lpv_gather_axis(emitter, d, a);
            any_light += axes[a];
          }
          if (!(any_light > 0.0)) continue;  // it faces away: no need to trace the line
          ivec3 start = lpv_gather_line_start(centre, emitter, lpv.scales.w, ivec3(dims));
          float through = OCCLUDED ? transmitted(start, cell, normalize(vec3(cell - start)), dims) : 1.0;
          if (!(through > 0.0)) continue;
          for (int a = 0; a < 6; ++a) cube[a] += through * flux_per_pi * axes[a];
        }
  }
  // Two texels a cell and channel: (+x, -x, +y, -y) and (+z, -z, 0, 0).
  int first = 2 * lpv_accumulated_texel(cell, push.cascade, dims);
  vec4 texels[6] = vec4[6](vec4(cube[0].r, cube[1].r, cube[2].r, cube[3].r), vec4(cube[4].r, cube[5].r, 0.0, 0.0),
                           vec4(cube[0].g, cube[1].g, cube[2].g, cube[3].g), vec4(cube[4].g, cube[5].g, 0.0, 0.0),
                           vec4(cube[0].b, cube[1].b, cube[2].b, cube[3].b), vec4(cube[4].b, cube[5].b, 0.0, 0.0));
  if (push.keep != 0u) {
    for (int k = 0; k < 2; ++k) {
      bounce_r[first + k] = texel_bits(texels[k]);
      bounce_g[first + k] = texel_bits(texels[2 + k]);
      bounce_b[first + k] = texel_bits(texels[4 + k]);
    }
  }
  for (int k = 0; k < 2; ++k) {
    // Later bounces add to the light of those before, in the order they ran.
    if (push.bounce != 0u) {
      texels[k] += texel_value(accumulated_r[first + k]);
      texels[2 + k] += texel_value(accumulated_g[first + k]);
      texels[4 + k] += texel_value(accumulated_b[first + k]);
    }
    accumulated_r[first + k] = texel_bits(texels[k]);
    accumulated_g[first + k] = texel_bits(texels[2 + k]);
    accumulated_b[first + k] = texel_bits(texels[4 + k]);
  }
}
