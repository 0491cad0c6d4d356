// The gather pass's interface: lpv_gather.comp and renderer/passes/lpv_gather_pass.cpp.
#ifndef LPV_GATHER_INTERFACE_H
#define LPV_GATHER_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

// lpv_gather_sources.comp: the lit injected cells, in cell order, written to the sources
// buffer (the propagation grids' memory, which the gather does not use): texel 0 holds their
// count (x, as an integer), then two texels each, what it emits (lpv_gather_emitter) and its
// channels' flux / pi with its cell index in w.
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
