// A sum of fluxes (of a grid, or of the VPLs), for the statistics: each cell's flux in 64-bit
// fixed point, summed across the subgroup and added to the work group's slot of the record
// (see LPV_FLUX_SLOTS) with one atomic per subgroup. Integer sums are exact, so the total does
// not depend on the order of anything: it is deterministic.
// Requires a `flux_stats` int64 buffer declared before the include.
#ifndef LPV_GRID_FLUX_GLSL
#define LPV_GRID_FLUX_GLSL

#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_EXT_shader_subgroup_extended_types_int64 : require

// Every invocation of the subgroup must call this (zero flux for invocations without a cell).
void add_grid_flux(vec3 flux, uint record, float units_per_watt) {
  uint group = gl_WorkGroupID.x + gl_NumWorkGroups.x * (gl_WorkGroupID.y + gl_NumWorkGroups.y * gl_WorkGroupID.z);
  uint slot = (record * LPV_FLUX_SLOTS + group % LPV_FLUX_SLOTS) * LPV_FLUX_SLOT_INT64S;
  for (uint c = 0u; c < 3u; ++c) {
    int64_t sum = subgroupAdd(to_fixed(flux[c], units_per_watt));
    if (subgroupElect() && sum != 0l) atomicAdd(flux_stats[slot + c], sum);
  }
}

#endif
