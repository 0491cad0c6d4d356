// The flux a grid holds, for the statistics: each work group sums its cells in a fixed order
// in shared memory and adds the sum to a fixed-point total, so the total is deterministic.
// Requires a GpuLpv-sized LPV_GROUP^3 work group and a `flux_stats` int64 buffer.
#ifndef LPV_GRID_FLUX_GLSL
#define LPV_GRID_FLUX_GLSL

shared vec3 group_flux[LPV_GROUP * LPV_GROUP * LPV_GROUP];

// Every invocation of the group must call this (it has barriers).
void add_group_flux(vec3 flux, uint stats_offset, float units_per_watt) {
  uint local = gl_LocalInvocationIndex;
  group_flux[local] = flux;
  barrier();
  for (uint stride = LPV_GROUP * LPV_GROUP * LPV_GROUP / 2u; stride > 0u; stride /= 2u) {
    if (local < stride) group_flux[local] += group_flux[local + stride];
    barrier();
  }
  if (local == 0u) {
    for (uint c = 0u; c < 3u; ++c)
      if (group_flux[0][c] != 0.0) atomicAdd(flux_stats[stats_offset + c], to_fixed(group_flux[0][c], units_per_watt));
  }
}

#endif
