// The RSM pass's interface: rsm.vert, rsm.frag and renderer/passes/rsm_pass.cpp. Its push
// constants, the draw's GpuDrawMaterial and then the view (layer) it draws, are declared
// field by field in the shaders: a struct holding both would be padded to 80 bytes in GLSL
// against 68 in C++ (rsm_pass.cpp checks the view's offset).
#ifndef LPV_RSM_INTERFACE_H
#define LPV_RSM_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

LPV_BINDING RSM_VIEWS = 0u;   // uniform: GpuRsmView[SHADE_MAX_SHADOW_VIEWS] (both stages)
LPV_BINDING RSM_LIGHTS = 1u;  // uniform: GpuLight[SHADE_MAX_LIGHTS] (fragment)

LPV_INTERFACE_END

#endif
