// The camera's raster passes' interface: gbuffer.vert (shared by both), gbuffer.frag and
// forward.frag, and renderer/passes/gbuffer_pass.cpp and forward_pass.cpp. Their push
// constants are the draw's GpuDrawMaterial (gpu_types.h); set 1 is the material's texture.
#ifndef LPV_CAMERA_RASTER_INTERFACE_H
#define LPV_CAMERA_RASTER_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

LPV_BINDING CAMERA_FRAME = 0u;  // uniform GpuFrame (gbuffer.vert; forward.frag too)

// forward.frag
LPV_BINDING FORWARD_SHADOW_MAPS = 1u;   // sampled with comparison: the shadow atlas
LPV_BINDING FORWARD_LIGHTS = 2u;        // uniform: GpuLight[SHADE_MAX_LIGHTS]
LPV_BINDING FORWARD_SHADOW_VIEWS = 3u;  // uniform: GpuShadowView[SHADE_MAX_SHADOW_VIEWS]
// The indirect light (lpv_irradiance.glsl): GpuLpv, then the accumulated grids' three
// channels as texels and the located walls, in this order (bind_indirect_light binds them
// from the first).
LPV_BINDING FORWARD_LPV = 4u;
LPV_BINDING FORWARD_ACCUMULATED_R = FORWARD_LPV + 1u;
LPV_BINDING FORWARD_ACCUMULATED_G = FORWARD_LPV + 2u;
LPV_BINDING FORWARD_ACCUMULATED_B = FORWARD_LPV + 3u;
LPV_BINDING FORWARD_WALLS = FORWARD_LPV + 4u;

LPV_INTERFACE_END

#endif
