// A sum of fluxes (of a grid, or of the VPLs), for the statistics: each cell's flux in 64-bit
// fixed point, summed across the work group and added to the total with one atomic per work
// group. Integer sums are exact, so the total does not depend on the order of anything: it
// is deterministic.
// Requires a `flux_stats` int64 buffer declared before the include.
#ifndef LPV_GRID_FLUX_GLSL
#define LPV_GRID_FLUX_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_EXT_shader_subgroup_extended_types_int64 : require

// Partial sums of the work group's subgroups (at most one per invocation).
shared int64_t grid_flux_partial[gl_WorkGroupSize.x * gl_WorkGroupSize.y * gl_WorkGroupSize.z][3];

// Every invocation of the work group must call this, in uniform control flow (zero flux for
// invocations without a cell). Summed across the subgroup, then across the work group, and
// added with one atomic per channel and work group: the statistics are one total that every
// core adds to, and contended atomics on one cache line had cost propagation about a tenth
// of its time when each subgroup added its own.
void add_grid_flux(vec3 flux, uint stats_offset, float units_per_watt) {
  int64_t sums[3];
  for (uint c = 0u; c < 3u; ++c) sums[c] = subgroupAdd(to_fixed(flux[c], units_per_watt));
  if (subgroupElect())
    for (uint c = 0u; c < 3u; ++c) grid_flux_partial[gl_SubgroupID][c] = sums[c];
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    for (uint c = 0u; c < 3u; ++c) {
      int64_t total = 0l;
      for (uint g = 0u; g < gl_NumSubgroups; ++g) total += grid_flux_partial[g][c];
      if (total != 0l) atomicAdd(flux_stats[stats_offset + c], total);
    }
  }
}

#endif
