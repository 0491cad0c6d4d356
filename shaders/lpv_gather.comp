#version 450
// The gather transfer (lpv_gather.h, docs/lpv.md "The gather"): each cell of a slab of layers
// sums the light of every lit injected cell of its cascade, the near ones one by one and those
// further off in blocks (the pyramid lpv_gather_sources.comp builds), each from where its light
// left its surfaces, its line of sight from the cell its light was added around
// (lpv_gather_line_start) through the faces of the geometry volume, into its irradiance cube. The sums run over levels and blocks in a fixed
// order, so the result is deterministic.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_shuffle : require
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
layout(set = 0, binding = GATHER_FACE_COVERS, rgba32f) uniform readonly imageBuffer face_covers;  // lpv_face_cover_texel
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
// The lines to far records (above level 0) walked once for each 2 x 2 x 2 block of cells, to
// its cell nearest the line's start, and per cell only the faces from there (lpv.far_lines
// "per_block", lpv_gather.h: lpv_gather_shared_end); else every line to every cell.
layout(constant_id = 1) const bool SHARED_FAR_LINES = false;
// A wall's two faces paired along each line (lpv.line_blocking "paired", lpv_gather.h "Blocking
// along a line"), else every face's projected blocking multiplied.
layout(constant_id = 2) const bool PAIRED_FACES = true;

// The line of the light along w from cell `source` to cell `target`, walked from cell `from` to
// cell `to` from the state `line` (lpv_gather.h, "Blocking along a line"): across the faces the
// line between their centres crosses, in the order it crosses them (lpv_gather_next_axis), each
// met as the line from source to target meets it (its blockers' plane must separate those ends).
// The whole line: from = source, to = target, from lpv_gather_line_begin().
vec4 walk(vec4 line, ivec3 from, ivec3 to, ivec3 source, ivec3 target, vec3 w, uvec3 dims) {
  ivec3 d = to - from;
  ivec3 span = abs(d);
  ivec3 step = ivec3(sign(vec3(d)));
  ivec3 next = ivec3(1);  // each axis's next crossing, t = next / (2 span)
  int crossings = span.x + span.y + span.z;
  ivec3 cell = from;
  for (int i = 0; i < crossings && lpv_gather_line_open(line); ++i) {
    int axis = lpv_gather_next_axis(next, span);
    ivec3 ahead = cell;
    ahead[axis] += step[axis];
    ivec3 owner = step[axis] > 0 ? cell : ahead;  // a face is stored with the cell below it
    vec3 face_centre = 0.5 * (vec3(cell) + vec3(ahead));
    vec3 to_source = vec3(source) - face_centre, to_target = vec3(target) - face_centre;
    if (PAIRED_FACES) {
      vec4 cover = imageLoad(face_covers, lpv_face_cover_texel(owner, axis, dims));
      line = lpv_gather_line_pair(line, axis, lpv_gather_face_cover(cover, axis, w, to_source, to_target));
    } else {
      vec4 b = imageLoad(faces, lpv_face_texel(owner, axis, dims));
      vec3 spread = imageLoad(faces, lpv_face_spread_texel(owner, axis, dims)).xyz;
      line = lpv_gather_line_multiply(line, lpv_gather_transmitted(b, spread, w, to_source, to_target));
    }
    cell = ahead;
    next[axis] += 2;
  }
  return line;
}

// The fraction of the light from a record's line start `start` that reaches `cell`.
float transmitted(ivec3 start, ivec3 cell, uvec3 dims) {
  vec3 w = normalize(vec3(cell - start));
  return lpv_gather_line_through(walk(lpv_gather_line_begin(), start, cell, start, cell, w, dims));
}

// The cell of this invocation in its work group of 4 x 4 x 4. With shared far lines, each run
// of 8 invocations (a lavapipe subgroup, or an eighth of a wider one) takes a 2 x 2 x 2 block,
// whose cells gather the same far records (their windows above level 0 depend on the parent
// and up: lpv_gather_window); else rows of 4 x 2 x 1, as the invocation IDs give.
ivec3 group_cell() {
  if (!SHARED_FAR_LINES) return ivec3(gl_LocalInvocationID);
  uint i = gl_LocalInvocationIndex;
  return 2 * ivec3((i >> 3u) & 1u, (i >> 4u) & 1u, (i >> 5u) & 1u) + ivec3(i & 1u, (i >> 1u) & 1u, (i >> 2u) & 1u);
}

// What a record sends to `cell` before the line's transmittance: per cube axis, per unit of
// its flux / pi (lpv_gather_axis), their sum (0: it faces away), and the cell its line of
// sight starts from (lpv_gather_line_start).
struct Arrival {
  float axes[6];
  float any_light;
  ivec3 start;
};
Arrival arrival_from(vec4 emitter, vec3 centre, ivec3 cell, uvec3 dims) {
  vec3 d = vec3(cell) - centre;
  Arrival a;
  a.any_light = 0.0;
  for (int k = 0; k < 6; ++k) {
    a.axes[k] = lpv_gather_axis(emitter, d, k);
    a.any_light += a.axes[k];
  }
  a.start = lpv_gather_line_start(centre, emitter, lpv.scales.w, ivec3(dims));
  return a;
}
Arrival arrival(int record, ivec3 cell, uvec3 dims) {
  return arrival_from(lpv_gather_emitter(imageLoad(sources, record), lpv.transfer.y), imageLoad(sources, record + 2).xyz,
                      cell, dims);
}

// The record of a window's block, and whether it holds any light.
int record_texel(ivec3 block, int first, ivec3 level_dims) {
  return LPV_GATHER_RECORD_TEXELS * (first + block.x + level_dims.x * (block.y + level_dims.y * block.z));
}
vec3 record_flux(int record) { return imageLoad(sources, record + 1).xyz; }
bool lit(vec3 flux_per_pi) { return flux_per_pi.x + flux_per_pi.y + flux_per_pi.z > 0.0; }

// A level above 0 with shared far lines: its window's records 8 at a time, each lane of the
// cell's 2 x 2 x 2 block reading one record and walking its line to the block once
// (lpv_gather_shared_end), the 8 cells taking the record and the walk by shuffles (a lane
// index every lane of the run shares: one permute, where 8 lanes loading the same texel made
// 8 loads) and adding their own last faces.
void gather_far_shared(LpvGatherWindow window, int level, ivec3 cell, bool inside, uvec3 dims, inout vec3 cube[6]) {
  ivec3 level_dims = lpv_gather_level_dims(ivec3(dims), level);
  int first = lpv_gather_level_first(ivec3(dims), level);
  ivec3 n = window.hi - window.lo + 1;
  int count = n.x * n.y * n.z;
  uint lane = gl_SubgroupInvocationID & 7u, block_lanes = gl_SubgroupInvocationID & ~7u;
  for (int base = 0; base < count; base += 8) {
    // The record this lane reads (none past the window's end, or gathered finer: the block's
    // cells share their parent, so it is gathered finer for all of them alike, or dark).
    vec4 shared_line = lpv_gather_line_blocked();
    vec3 flux = vec3(0.0), centre = vec3(0.0);
    vec4 emitter = vec4(0.0);
    int p = base + int(lane);
    if (p < count) {
      ivec3 block = window.lo + ivec3(p % n.x, (p / n.x) % n.y, p / (n.x * n.y));
      int record = record_texel(block, first, level_dims);
      if (!lpv_gather_gathered_finer(block, cell, level)) flux = record_flux(record);
      if (lit(flux)) {
        emitter = lpv_gather_emitter(imageLoad(sources, record), lpv.transfer.y);
        centre = imageLoad(sources, record + 2).xyz;
        ivec3 start = lpv_gather_line_start(centre, emitter, lpv.scales.w, ivec3(dims));
        ivec3 end = lpv_gather_shared_end(start, cell, ivec3(dims));
        shared_line = walk(lpv_gather_line_begin(), start, end, start, end, normalize(vec3(end - start)), dims);
      }
    }
    for (int j = 0; j < 8 && base + j < count; ++j) {
      uint lane_j = block_lanes | uint(j);
      vec4 line_to_end = PAIRED_FACES ? subgroupShuffle(shared_line, lane_j) : vec4(subgroupShuffle(shared_line.x, lane_j), 0.0, 0.0, 0.0);
      // Shuffled by every lane before any branch: a shuffle reads only lanes that run it.
      vec3 flux_per_pi = subgroupShuffle(flux, lane_j);
      vec4 emitter_j = subgroupShuffle(emitter, lane_j);
      vec3 centre_j = subgroupShuffle(centre, lane_j);
      if (inside && lpv_gather_line_open(line_to_end) && lit(flux_per_pi)) {
        Arrival a = arrival_from(emitter_j, centre_j, cell, dims);
        if (a.any_light > 0.0) {
          ivec3 end = lpv_gather_shared_end(a.start, cell, ivec3(dims));
          vec4 line = walk(line_to_end, end, cell, a.start, cell, normalize(vec3(cell - a.start)), dims);
          float through = lpv_gather_line_through(line);
          for (int k = 0; k < 6; ++k) cube[k] += through * flux_per_pi * a.axes[k];
        }
      }
    }
  }
}

void main() {
  GpuLpvCascade g = lpv.cascades[push.cascade];
  uvec3 dims = g.dims.xyz;
  ivec3 cell = ivec3(gl_WorkGroupID) * int(LPV_GROUP) + group_cell() + ivec3(0, 0, int(push.first_layer));
  bool inside = all(lessThan(cell, ivec3(dims))) && cell.z < int(push.first_layer + push.layers);
  // With shared far lines every lane of a block takes part in its shuffles: one past the grid's
  // end walks lines for the others and stores nothing.
  if (!inside && !(SHARED_FAR_LINES && OCCLUDED)) return;
  vec3 cube[6] = vec3[6](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
  bool last = false;
  for (int level = 0; !last; ++level) {
    LpvGatherWindow window = lpv_gather_window(cell, level, ivec3(dims));
    last = window.last;
    if (SHARED_FAR_LINES && OCCLUDED && level > 0) {
      gather_far_shared(window, level, cell, inside, dims, cube);
      continue;
    }
    if (!inside) continue;
    ivec3 level_dims = lpv_gather_level_dims(ivec3(dims), level);
    int first = lpv_gather_level_first(ivec3(dims), level);
    for (int z = window.lo.z; z <= window.hi.z; ++z)
      for (int y = window.lo.y; y <= window.hi.y; ++y)
        for (int x = window.lo.x; x <= window.hi.x; ++x) {
          ivec3 block = ivec3(x, y, z);
          if (lpv_gather_gathered_finer(block, cell, level)) continue;
          int record = record_texel(block, first, level_dims);
          vec3 flux_per_pi = record_flux(record);
          if (!lit(flux_per_pi)) continue;  // no light there
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
          Arrival a = arrival(record, cell, dims);
          if (!(a.any_light > 0.0)) continue;  // it faces away: no need to trace the line
          float through = OCCLUDED ? transmitted(a.start, cell, dims) : 1.0;
          if (!(through > 0.0)) continue;
          for (int k = 0; k < 6; ++k) cube[k] += through * flux_per_pi * a.axes[k];
        }
  }
  if (!inside) return;
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
