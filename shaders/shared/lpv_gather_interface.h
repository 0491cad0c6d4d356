// The gather pass's interface: lpv_gather.comp and renderer/passes/lpv_gather_pass.cpp.
#ifndef LPV_GATHER_INTERFACE_H
#define LPV_GATHER_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

// lpv_gather_sources.comp: the pyramid of the sources (lpv_gather.h: LPV_GATHER_RECORD_TEXELS
// a record, lpv_gather_records of them), written to the sources buffer (the propagation
// grids' memory, which the gather does not use, sized for it: LpvVolumes::grids).
LPV_BINDING GATHER_SOURCES_LPV = 0u;       // uniform GpuLpv
LPV_BINDING GATHER_SOURCES_INJECTED = 1u;  // texels: the injection's integer sums
LPV_BINDING GATHER_SOURCES_STORE = 2u;     // storage: the sources, written

// lpv_gather.comp
LPV_BINDING GATHER_LPV = 0u;       // uniform GpuLpv
LPV_BINDING GATHER_INJECTED = 1u;  // texels: the injection's integer sums, 6 texels of 2 a cell
LPV_BINDING GATHER_FACES = 2u;     // texels: the geometry volume's faces (lpv_face_texel)
LPV_BINDING GATHER_SOURCES = 6u;   // texels: the sources (above)
LPV_BINDING GATHER_ACCUMULATED_STORE_R = 3u;  // storage: the irradiance cubes, written
LPV_BINDING GATHER_ACCUMULATED_STORE_G = 4u;
LPV_BINDING GATHER_ACCUMULATED_STORE_B = 5u;

struct LpvGatherPush {
  uint cascade;
  uint first_layer;  // the layers of cells along z this dispatch gathers for: a gather is
  uint layers;       // cut in slabs, so that a render can be stopped between them
};

LPV_INTERFACE_END

#endif
