// The shading pass's interface: shade.comp and renderer/passes/shade_pass.cpp.
#ifndef LPV_SHADE_INTERFACE_H
#define LPV_SHADE_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

LPV_BINDING SHADE_FRAME = 0u;            // uniform GpuFrame
LPV_BINDING SHADE_G_POSITION = 1u;       // storage images: the G-buffer
LPV_BINDING SHADE_G_NORMAL = 2u;
LPV_BINDING SHADE_G_ALBEDO = 3u;
LPV_BINDING SHADE_SHADOW_MAPS = 4u;      // sampled with comparison: the shadow atlas
LPV_BINDING SHADE_LIGHTS = 5u;           // storage: GpuLight
LPV_BINDING SHADE_SHADOW_VIEWS = 6u;     // storage: the shadow views (GpuShadowView)
LPV_BINDING SHADE_MATERIALS = 7u;        // storage: GpuMaterial
LPV_BINDING SHADE_LINEAR = 8u;           // storage: the linear image, written
// The indirect light (lpv_irradiance.glsl): GpuLpv, then the accumulated grids' three
// channels as texels and the located walls, in this order (bind_indirect_light binds them
// from the first).
LPV_BINDING SHADE_LPV = 9u;
LPV_BINDING SHADE_ACCUMULATED_R = SHADE_LPV + 1u;
LPV_BINDING SHADE_ACCUMULATED_G = SHADE_LPV + 2u;
LPV_BINDING SHADE_ACCUMULATED_B = SHADE_LPV + 3u;
LPV_BINDING SHADE_WALLS = SHADE_LPV + 4u;
LPV_BINDING SHADE_DISPLAY = 14u;         // storage: the display image, written

LPV_INTERFACE_END

#endif
