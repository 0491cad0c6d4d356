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
LPV_BINDING GATHER_FACE_COVERS = 10u;  // texels: their cover texels (lpv_face_cover_texel), for paired faces
LPV_BINDING GATHER_SOURCES = 6u;   // texels: the sources (above)
LPV_BINDING GATHER_ACCUMULATED_STORE_R = 3u;  // storage: the irradiance cubes, summed over the bounces
LPV_BINDING GATHER_ACCUMULATED_STORE_G = 4u;
LPV_BINDING GATHER_ACCUMULATED_STORE_B = 5u;
LPV_BINDING GATHER_BOUNCE_STORE_R = 7u;  // storage: this bounce's irradiance cubes alone, written
LPV_BINDING GATHER_BOUNCE_STORE_G = 8u;  // where another bounce follows (push.keep)
LPV_BINDING GATHER_BOUNCE_STORE_B = 9u;

struct LpvGatherPush {
  uint cascade;
  uint first_layer;  // the layers of cells along z this dispatch gathers for: a gather is
  uint layers;       // cut in slabs, so that a render can be stopped between them
  uint bounce;       // 0: the first, which the accumulated cubes start from; else added to them
  uint keep;         // 1: the cubes of this bounce are also stored alone, for the next one
};

// lpv_gather_bounce.comp: the scene's surfels reflect the last bounce's light as VPLs of the
// next (the injection's sums, cleared first), each on the side it faces; their flux is summed
// into a record of the flux statistics.
LPV_BINDING GATHER_BOUNCE_LPV = 0u;       // uniform GpuLpv
LPV_BINDING GATHER_BOUNCE_BLOCKERS = 1u;  // storage: GpuBlocker, the scene's surfels
LPV_BINDING GATHER_BOUNCE_LIGHT_R = 2u;   // texels: the last bounce's irradiance cubes
LPV_BINDING GATHER_BOUNCE_LIGHT_G = 3u;
LPV_BINDING GATHER_BOUNCE_LIGHT_B = 4u;
LPV_BINDING GATHER_BOUNCE_INJECTED = 5u;    // storage: the injection's integer sums, added to
LPV_BINDING GATHER_BOUNCE_FLUX_STATS = 6u;  // storage: the flux statistics
LPV_BINDING GATHER_BOUNCE_WALLS = 7u;       // texels: the located walls (LpvVolumes::walls)

struct LpvGatherBouncePush {
  uint cascade;
  uint count;        // surfels
  uint flux_record;  // where their reflected flux is summed
};

// lpv_gather_tail.comp: the bounces after the last one gathered, estimated (docs/lpv.md,
// "Bounces"): the last bounce's cubes times r / (1 - r), r = the flux its light reflects over
// the flux it was gathered from, per channel, at most LPV_BOUNCE_TAIL_MAX_RATIO.
LPV_BINDING GATHER_TAIL_LPV = 0u;
LPV_BINDING GATHER_TAIL_FLUX_STATS = 1u;  // storage: the flux statistics
LPV_BINDING GATHER_TAIL_LIGHT_R = 2u;     // texels: the last bounce's irradiance cubes
LPV_BINDING GATHER_TAIL_LIGHT_G = 3u;
LPV_BINDING GATHER_TAIL_LIGHT_B = 4u;
LPV_BINDING GATHER_TAIL_ACCUMULATED_R = 5u;  // storage: the accumulated cubes, added to
LPV_BINDING GATHER_TAIL_ACCUMULATED_G = 6u;
LPV_BINDING GATHER_TAIL_ACCUMULATED_B = 7u;

struct LpvGatherTailPush {
  uint cascade;
  uint gathered_record;   // the flux the last bounce was gathered from
  uint reflected_record;  // the flux its light reflects: the next bounce's
};

LPV_INTERFACE_END

#endif
