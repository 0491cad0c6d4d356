// The propagation pass's interface: lpv_propagate.comp and renderer/passes/lpv_propagate_pass.cpp.
#ifndef LPV_PROPAGATE_INTERFACE_H
#define LPV_PROPAGATE_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

// The grids and the accumulated light are read as texel buffers and written as storage
// buffers: views of the same memory (vkx::TexelBuffer and texel_store.glsl say why).
LPV_BINDING PROPAGATE_LPV = 0u;               // uniform GpuLpv
LPV_BINDING PROPAGATE_GRIDS = 1u;             // texels: the two grids, in sender form
LPV_BINDING PROPAGATE_ACCUMULATED_R = 2u;     // texels: the light summed over the iterations
LPV_BINDING PROPAGATE_ACCUMULATED_G = 3u;
LPV_BINDING PROPAGATE_ACCUMULATED_B = 4u;
LPV_BINDING PROPAGATE_FACES = 5u;             // texels: the geometry volume's faces
LPV_BINDING PROPAGATE_FLUX_STATS = 6u;        // storage: the flux statistics
LPV_BINDING PROPAGATE_GRID_STORE = 7u;        // storage: the grids, written
LPV_BINDING PROPAGATE_ACCUMULATED_STORE_R = 8u;
LPV_BINDING PROPAGATE_ACCUMULATED_STORE_G = 9u;
LPV_BINDING PROPAGATE_ACCUMULATED_STORE_B = 10u;
LPV_BINDING PROPAGATE_FACE_ALBEDO = 11u;      // texels: the faces' blockers' mean albedo

struct LpvPropagatePush {
  uint cascade;
  uint stats_record;  // the flux statistics' record of this iteration
  uint iteration;     // 1-based
};

LPV_INTERFACE_END

#endif
