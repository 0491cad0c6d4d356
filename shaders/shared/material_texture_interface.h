// The material's texture, as every raster pass that draws materials binds it (rsm.frag, and
// material_surface.glsl for gbuffer.frag and forward.frag): descriptor set 1, after the
// pass's own set 0, holding the base colour as one combined image sampler. Its C++ side:
// TextureSetLayout (renderer/material_textures.cpp) and GpuScene::draw_all, which binds it.
#ifndef LPV_MATERIAL_TEXTURE_INTERFACE_H
#define LPV_MATERIAL_TEXTURE_INTERFACE_H

#include "pass_interface.h"

LPV_INTERFACE_BEGIN

LPV_BINDING MATERIAL_TEXTURE_SET = 1u;
LPV_BINDING MATERIAL_BASE_COLOR = 0u;  // sampler2D, read when the TEXTURED constant is set

LPV_INTERFACE_END

#endif
