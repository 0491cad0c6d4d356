// The injection pass's interface: lpv_inject.comp (the RSMs' VPLs), lpv_inject_emitters.comp
// (emissive surfaces' VPLs), lpv_inject_resolve.comp (their integer sums to the grids), and
// renderer/passes/lpv_inject_pass.cpp.
#ifndef LPV_INJECT_INTERFACE_H
#define LPV_INJECT_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

// lpv_inject.comp
LPV_BINDING INJECT_LPV = 0u;           // uniform GpuLpv
LPV_BINDING INJECT_RSM_POSITION = 1u;  // storage images: the RSMs
LPV_BINDING INJECT_RSM_NORMAL = 2u;
LPV_BINDING INJECT_RSM_FLUX = 3u;
LPV_BINDING INJECT_INJECTED = 4u;      // storage: the integer sums, 12 a cell (RGB x SH)
LPV_BINDING INJECT_FLUX_STATS = 5u;    // storage: the flux statistics
LPV_BINDING INJECT_WALLS = 6u;         // texels: the located walls (LpvVolumes::walls)

// lpv_inject_emitters.comp
LPV_BINDING INJECT_EMITTERS_LPV = 0u;
LPV_BINDING INJECT_EMITTERS_EMITTERS = 1u;  // storage: GpuEmitter
LPV_BINDING INJECT_EMITTERS_INJECTED = 2u;
LPV_BINDING INJECT_EMITTERS_FLUX_STATS = 3u;

// lpv_inject_resolve.comp
LPV_BINDING INJECT_RESOLVE_LPV = 0u;
LPV_BINDING INJECT_RESOLVE_INJECTED = 1u;  // texels: the sums, 6 texels of 2 a cell
LPV_BINDING INJECT_RESOLVE_GRIDS = 2u;     // storage: the grids, written
LPV_BINDING INJECT_RESOLVE_ACCUMULATED_R = 3u;
LPV_BINDING INJECT_RESOLVE_ACCUMULATED_G = 4u;
LPV_BINDING INJECT_RESOLVE_ACCUMULATED_B = 5u;
LPV_BINDING INJECT_RESOLVE_FLUX_STATS = 6u;

// lpv_inject.comp: one light view's RSM layer
struct LpvInjectRsmPush {
  uint cascade;
  uint stats_record;   // the flux statistics' record
  uint layer;          // the view's layer of the RSMs
  uint vpls_per_side;  // its VPLs a side: its texels a side (GpuRsmView::info.z) / vpl_downsample
  uint merge;          // 1: tiles of LPV_INJECT_TILE^2 VPLs an invocation, merged where close; 0: one
};

// lpv_inject_resolve.comp
struct LpvInjectPush {
  uint cascade;
  uint stats_record;  // the flux statistics' record
};

// lpv_inject_emitters.comp
struct LpvInjectEmittersPush {
  uint cascade;
  uint stats_record;
  uint count;  // emitters
};

LPV_INTERFACE_END

#endif
